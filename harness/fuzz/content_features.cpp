#include "fuzz/content_features.h"

#include "case/inactive.h"
#include "parse/parse_case.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// Whether a geometry of `kind` in `s` has an inactive primitive.
bool inactivePrimitive(const Scene& s, Geometry::Kind kind) {
  for (const Blas& b : s.blases)
    for (const Geometry& g : b.geometries)
      if (g.kind == kind)
        for (uint32_t p = 0; p < g.primitiveCount(); ++p)
          if (primitiveInactive(g, p)) return true;
  return false;
}

bool nullInstance(const Scene& s) {
  for (const Instance& i : s.instances)
    if (!i.blas) return true;
  return false;
}

// What the scene holds in one of its states (as built, after an update).
void sceneFeatures(const Scene& s, std::set<std::string>& out) {
  if (inactivePrimitive(s, Geometry::Kind::Triangles)) out.insert("nan-vertex");
  if (inactivePrimitive(s, Geometry::Kind::Aabbs)) out.insert("nan-box");
  if (nullInstance(s)) out.insert("inactive-instance");
}

// A statement after a trace (in the order the program is written) reads a
// nestedHitBuiltin.
bool readsHitBuiltinAfterTrace(const Program& p) {
  bool traced = false, reads = false;
  walkStatements(p, [&](const Stmt& s) {
    if (traced)
      walkOwnExpressions(s, [&](const Expr& e) {
        reads = reads || (e.kind == Expr::Kind::Builtin && nestedHitBuiltin(e.builtin));
      });
    traced = traced || s.kind == Stmt::Kind::Trace;
  });
  return reads;
}

// A program reads gl_WorldRayOriginEXT or gl_WorldRayDirectionEXT.
bool readsWorldRay(const Program& p) {
  bool reads = false;
  walkStatements(p, [&](const Stmt& s) {
    walkOwnExpressions(s, [&](const Expr& e) {
      reads = reads || (e.kind == Expr::Kind::Builtin &&
                        (e.builtin == kBiWorldOrigin || e.builtin == kBiWorldDirection));
    });
  });
  return reads;
}

// A hit group without shaders beside a miss program that reads the world
// ray (references/driver-reports/lavapipe-miss-reads-neighbour-barycentrics.md).
bool missBesideEmptyGroup(const Pipeline& p) {
  bool empty = false, reads = false;
  for (const HitGroup& h : p.hit_groups)
    empty = empty || (!h.closest_hit && !h.any_hit && !h.intersection);
  for (const Program& m : p.miss) reads = reads || readsWorldRay(m);
  return empty && reads;
}

// What the programs compute with: a value of a sized type, a struct local.
void typedState(const Pipeline& p, std::set<std::string>& out) {
  const auto program = [&](const Program& prog) {
    walkStatements(prog, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Struct) out.insert("struct-local");
      for (const auto& [member, type] : s.params)
        if (isSized(type)) out.insert("sized-values");
      if (s.kind == Stmt::Kind::Array && isSized(s.local_type)) out.insert("sized-values");
    });
    walkExpressions(prog, [&](const Expr& e) {
      if (isSized(e.type)) out.insert("sized-values");
    });
  };
  program(p.raygen);
  for (const Program& m : p.miss) program(m);
  for (const HitGroup& h : p.hit_groups)
    for (const std::optional<Program>* s : {&h.closest_hit, &h.any_hit, &h.intersection})
      if (*s) program(**s);
  for (const Program& k : p.callables) program(k);
}

}  // namespace

const std::vector<std::string>& contentFeatureNames() {
  static const std::vector<std::string> kNames = {"nan-vertex",
                                                  "nan-box",
                                                  "inactive-instance",
                                                  "first-vertex",
                                                  "hit-builtin-after-trace",
                                                  "miss-world-ray-beside-empty-group",
                                                  "sized-values",
                                                  "struct-local"};
  return kNames;
}

bool nestedHitBuiltin(Builtin b) {
  return b == kBiInstance || b == kBiCustomIndex || b == kBiPrimitive || b == kBiGeometry ||
         b == kBiHitKind || isInstanceTransform(b);
}

std::set<std::string> contentFeatures(const Case& c) {
  std::set<std::string> out;
  sceneFeatures(c.scene, out);
  for (const auto& earlier : c.scene.earlier) sceneFeatures(*earlier, out);
  if (c.scene.build.first_vertex) out.insert("first-vertex");
  for (const HitGroup& h : c.pipeline.hit_groups)
    if (h.closest_hit && readsHitBuiltinAfterTrace(*h.closest_hit))
      out.insert("hit-builtin-after-trace");
  if (missBesideEmptyGroup(c.pipeline)) out.insert("miss-world-ray-beside-empty-group");
  typedState(c.pipeline, out);
  return out;
}

std::set<std::string> contentFeatures(const std::string& yaml) {
  const ParseResult parsed = parseCaseText(yaml, "case.yaml", "case");
  return parsed.value ? contentFeatures(*parsed.value) : std::set<std::string>{};
}

}  // namespace rayspec
