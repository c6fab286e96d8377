// The state of one case's generation (fuzz/generate_case.h): the seeded
// sequence, the YAML written so far, and what the scene holds that the rays
// and programs must fit. Each part is written by a file of its own:
// generate_scene.cpp, generate_rays.cpp, generate_programs.cpp.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "case/case.h"
#include "case/seeded_random.h"
#include "fuzz/generator_features.h"
#include "program/program.h"

namespace rayspec {

class CaseGenerator {
 public:
  CaseGenerator(uint64_t seed, const GeneratorFeatures& allowed)
      : rng_(seed), typed_rng_(seed ^ kTypedStream), allowed_(allowed) {}

  // The parts, in the order of the file.
  void scene();
  void rays();
  void pipeline();
  void outputs();

  std::string& text() { return out_; }
  std::set<std::string>& features() { return features_; }

  // The seeded draws: a whole number in [0, n), a chance, a number in
  // [lo, hi) rounded to eighths (printed exactly), one of a list.
  uint64_t pick(uint64_t n) { return n ? rng_.next() % n : 0; }
  bool chance(double p) { return rng_.unit() < p; }
  double eighths(double lo, double hi);
  template <typename T>
  const T& oneOf(const std::vector<T>& v) {
    return v[pick(v.size())];
  }

  // A number as the case file writes it (a Float always with a '.').
  static std::string num(double v);
  std::string vec3(double lo, double hi);

  // A random Uint expression of `stage` (fuzz/stage_vocabulary.h), nested
  // at most `depth` operators deep; a random Bool condition over one
  // (generate_expressions.cpp).
  std::string uintExpr(Stage stage, int depth);
  std::string condition(Stage stage);

 private:
  // Scene parts (generate_scene.cpp).
  void blasList();
  bool triangleGeometry(Geometry& g);  // true: a mesh shape
  void explicitTriangles(Geometry& g);
  void aabbGeometry(Geometry& g);
  void instance();
  std::string transform(Transform& m);
  std::string instanceFlags();
  // Layouts, updates and copies (generate_layout.cpp).
  void buildLayout();
  void updates();
  std::string updateStep();
  std::string drawFormat(Geometry& g);
  Vec3 drawVertex(VertexFormat f);
  std::array<float, 6> drawBox();
  // Ray parts (generate_rays.cpp).
  std::string rayFlags();
  std::string listRay();
  std::string wanderingRay();
  std::string launch(uint64_t w, uint64_t h);
  // Rays aimed at generated primitives (generate_aim.cpp).
  struct Placed;
  std::optional<std::string> aimedRay();
  std::string aimedText(const Placed& inst, const Geometry& g, DVec3 at, DVec3 along,
                        const std::string& feature);
  std::string aimForm();
  bool activeBoxes() const;
  // The pipeline's programs (fuzz/program_generator.h).
  friend class ProgramGenerator;
  std::string uintAtom(Stage stage);

  struct Blas {
    std::string name;
    bool aabbs = false;
    size_t geometries = 0;
    std::vector<Geometry> data;  // as built, then as the last update left them
    std::vector<bool> shaped;    // a mesh shape (fan, grid, triangulation): not updated
  };
  // An active instance: its BLAS, its transform as the last update left it.
  struct Placed {
    size_t blas = 0;
    Transform transform = kIdentity;
  };
  // A range of hit groups one or more instances reach (sbt_offset .. + geometries).
  struct GroupRange {
    size_t first = 0, count = 0;
    bool aabbs = false;
    size_t blas = 0;
  };

  SeededRandom rng_;
  // The stream typed live state is drawn from (generate_typed_state.cpp:
  // swapStreams while it draws), so that its draws leave rng_'s sequence as
  // it was: a case without typed state is the case of the generator before it.
  static constexpr uint64_t kTypedStream = 0x5DEECE66DA3B6F1Full;
  SeededRandom typed_rng_;
  void swapStreams() { std::swap(rng_, typed_rng_); }
  GeneratorFeatures allowed_;  // the device features drawn (--without leaves some out)
  std::string out_;
  std::set<std::string> features_;
  std::vector<Blas> blas_;
  std::vector<GroupRange> ranges_;
  std::vector<std::optional<Placed>> instances_;  // empty: an inactive instance
  size_t updates_ = 0;                            // scene.update steps
  std::string copy_ = "none";                     // scene.build.copy
  size_t hit_groups_ = 0;
  std::vector<bool> group_aabbs_;  // each hit group's kind
  size_t miss_count_ = 1;
  size_t callable_count_ = 0;
  bool sbt_stride_zero_ = false;
  std::set<std::string> fields_;    // per-ray fields some program records
  std::set<std::string> counters_;  // counters some program counts
  // Some ray is aimed at a shared edge or vertex, or grazes (rays()): its
  // legal answers, a pass between the triangles among them (R-WATERTIGHT),
  // differ in what it counts and records (see outputs()).
  bool edge_rays_ = false;
  bool indirect_ = false;  // rays.command: indirect (a trace command: raygen not a compute shader)
};

}  // namespace rayspec
