// What one execution of a case produced, device or model, in one schema.
// A results bundle on disk is a folder: results.json (everything below but the
// image pixels), records.bin (the raw per-ray words), and one NAME.raw per
// image (raw little-endian 32-bit texels) plus NAME.png / NAME.exr when the
// binary is built with OpenImageIO. See bundle/results_io.h.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/source_loc.h"
#include "results/record_layout.h"
#include "results/step_cost.h"
#include "results/undefined_reason.h"

namespace rayspec {

// std::allocator, except that a construct without a value default-initialises:
// resize(n) of plain words leaves them unwritten. The model's records of a
// million rays are 176 MB (and an rgba32f image 16 MB): zeroed by one thread
// before the trace, they were half of a threaded run's time; its workers
// clear (records) or write (texels) their own chunks instead.
template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
// Per-ray records and image texels: resize(n) leaves them unwritten,
// assign(n, 0) zeroes.
using BulkWords = std::vector<uint32_t, DefaultInitAllocator<uint32_t>>;

struct Image {
  std::string name;
  std::string field;  // record field it shows
  uint32_t width = 0, height = 0, channels = 1;
  bool is_float = false;  // rgba32f (channels 4) or r32ui (channels 1)
  BulkWords texels;       // width*height*channels words (float bits when is_float)
};

// How one side's execution (device or model) of a case ended; the detail
// says why. Not the verdict's Status (compare/verdict.h), which judges both.
// Refused: the driver refused something a conformant driver must accept (a
// valid pipeline within the limits): the case Fails.
// InvalidShader: a stage rayspec generated did not compile or validate (our
// error, never the device's: the case gets CaseError).
#define RAYSPEC_SIDE_STATUSES(X)  \
  X(Ok, "ok")                     \
  X(NotSupported, "NotSupported") \
  X(Crash, "Crash") X(Timeout, "Timeout") X(Refused, "Refused") X(InvalidShader, "InvalidShader")
enum class SideStatus { RAYSPEC_SIDE_STATUSES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(SideStatus, RAYSPEC_SIDE_STATUSES);
inline const char* sideStatusName(SideStatus s) {
  return nameOf(s);
}
inline bool parseSideStatus(const std::string& name, SideStatus* out) {
  return parseEnumName(name, out);
}

// Why the model's exact tier found a ray numerically ambiguous. Stable names
// (results.json): see ambiguityReasonName().
// Rows: X(AmbiguityReason, "name", the rule a device answering outside the legal set breaks).
#define RAYSPEC_AMBIGUITY_REASONS(X)                                                           \
  /* near an edge shared by two triangles (or a border edge) */                                \
  X(Edge, "edge", "R-WATERTIGHT")                                                              \
  X(Vertex, "vertex", "R-WATERTIGHT") /* near a vertex (two or more edges within the bound) */ \
  X(TmaxTie, "tmax-tie", "R-TIE")     /* a hit within rounding of tmax */                      \
  X(TminTie, "tmin-tie", "R-TIE")     /* a hit within rounding of tmin */                      \
  X(TTie, "t-tie", "R-TIE")           /* equal t in different primitives or instances */       \
  /* TerminateOnFirstHit: which hit comes first is unspecified (R-TOFH) */                     \
  X(FirstHit, "first-hit", "R-TOFH")                                                           \
  /* the answer depends on the traversal order (a terminating any-hit, R-ORDER-UNSPEC) */      \
  X(Order, "order", "R-ORDER-UNSPEC")                                                          \
  X(AabbFace, "aabb-face", "R-AABB-CONS") /* the ray passes within rounding of an AABB face */ \
  /* an intersection program's decision within rounding (R-PREC) */                            \
  X(ShaderArith, "shader-arith", "R-PREC")                                                     \
  /* the ray runs in a triangle's plane: a hit anywhere across it, or none (R-PREC) */         \
  X(InPlane, "in-plane", "R-PREC")
enum class AmbiguityReason { RAYSPEC_AMBIGUITY_REASONS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(AmbiguityReason, RAYSPEC_AMBIGUITY_REASONS);
inline const char* ambiguityReasonName(AmbiguityReason r) {
  return nameOf(r);
}
inline bool parseAmbiguityReason(const std::string& name, AmbiguityReason* out) {
  return parseEnumName(name, out);
}
// The rule a device answering outside the legal set breaks.
const char* ruleForAmbiguity(AmbiguityReason r);

struct UndefinedRay {
  uint32_t ray = 0;  // launch index y * width + x
  UndefinedReason reason = UndefinedReason::RayParameters;
  std::string what;  // names the case field, e.g. "pipeline.raygen: call index 5, 2 callables"
};

// A ray the model's exact tier found numerically ambiguous, with the answers
// the specification allows for it.
struct Candidate {
  bool hit = false;  // false: a miss is a legal answer
  uint32_t instance = 0, geometry = 0, primitive = 0;
  // A hit's t as that answer commits it; NaN where unknown (a miss, or a
  // results.json written before candidates carried it).
  double t = std::numeric_limits<double>::quiet_NaN();
};
// One legal answer of an ambiguous ray replayed through the whole launch
// ray (model/legal_replays.cpp): every choice its ambiguous traces may make,
// raygen, closest-hit, miss and callables run as that choice makes them run.
// `record`: the launch ray's record so (empty where the case keeps none);
// `counter_moves`: how far it moves each counter from the model's own run
// (only the counters it moves).
struct LegalReplay {
  std::vector<uint32_t> record;
  std::map<std::string, int64_t> counter_moves;
  bool operator==(const LegalReplay&) const = default;
};

struct RayAmbiguity {
  uint32_t ray = 0;  // launch index y * width + x
  AmbiguityReason reason = AmbiguityReason::Edge;
  std::vector<Candidate> candidates;
  // edge / vertex: the triangles the model found within the error bound of
  // the shared edge or vertex (each once; `hit`: the model's own decision,
  // one of them where the mesh is closed); a watertight device finds one.
  std::vector<Candidate> shared_triangles;
  // Answers a device reaches only by passing between the triangles of a
  // shared edge or vertex (R-WATERTIGHT, a "should"): none of them is in
  // `candidates`; a device taking one gets a QualityWarning, not a Fail.
  std::vector<Candidate> leak_answers;
  // Each distinct outcome of the ray's legal answers, the model's own among
  // them; empty where there are more than the model replays
  // (kMaxLegalReplays) or a bundle saved without them: then only what every
  // answer shares is judged.
  std::vector<LegalReplay> replays;
  // Each distinct outcome, none of `replays`, of the ray replayed with a
  // leak answer taken where its first ambiguous trace or a later one has
  // one (model/legal_replays.h): a record that is one of them passed
  // between triangles (R-WATERTIGHT, a QualityWarning) where the record
  // names no hit to tell; empty where there are none, past the bounds, or
  // in a bundle saved without them.
  std::vector<LegalReplay> leak_replays;
  // Each distinct outcome, none of `replays` or `leak_replays`, of the ray
  // replayed with a double hit taken where a trace has one: two or more
  // triangles of a group closing around the ray decided as hits, each subset
  // in the orders whose effects differ (model/legal_replays.h): a record
  // that is one of them ran any-hit on several triangles of one edge or
  // vertex (R-WATERTIGHT, a QualityWarning); empty where there are none,
  // past the bounds, or in a bundle saved without them.
  std::vector<LegalReplay> double_replays;
  // How many of the ray's traces were ambiguous in the model's own run (a
  // ray traced twice through one vertex: 2); each may move a counter.
  uint32_t traces = 1;
  // The ambiguous traversal (the ray's first) is a ray query's, not a
  // trace's: its answer runs no shader and shows only in what the query's
  // blocks and the statements after it write (compare/trace_shape.h
  // queryReachedFields), never in the trace's hit, miss and run fields.
  bool from_query = false;
};

// A ray whose hit t a device may compute further from the model's than the
// default tolerance allows (exact tier; the rounding of an intersection
// program's arithmetic, such as a sphere root near tangency, R-PREC).
struct TBound {
  uint32_t ray = 0;
  float bound = 0;  // |device t - model t| may reach this
};

// R-AHIT-DUP: a ray some of whose compared fields a device that runs any-hit
// more than once for a primitive may leave otherwise (model/any_hit_repeat.h).
struct RepeatDependentRay {
  uint32_t ray = 0;
  FieldMask fields = 0;  // fieldBit(i): recordFields()[i]
};

// What the device broke that only the device shows, and the rule it breaks.
struct DeviceFinding {
  std::string rule;
  std::string message;
  bool operator==(const DeviceFinding&) const = default;
};

struct Results {
  bool ok() const { return status == SideStatus::Ok; }
  // "ok", or "Crash: <detail>".
  std::string statusText() const;
  void setStatus(SideStatus s, std::string detail) {
    status = s;
    status_detail = std::move(detail);
  }

  std::string case_name;
  std::string backend;  // "vulkan" or "model"
  std::string device;   // Vulkan device name, or "embree-<tier>"
  std::string driver;   // Vulkan driverInfo ("Mesa 25.0.7"); "" for the model or unknown
  SideStatus status = SideStatus::Ok;
  std::string status_detail;  // why, when status is not Ok
  uint32_t width = 0, height = 0;
  std::map<std::string, uint64_t> counters;
  BulkWords records;  // width*height*recordWords() words
  std::vector<Image> images;
  std::vector<RayAmbiguity> ambiguous;  // model, exact tier: rays that are not clear
  std::vector<TBound> t_bounds;         // model, exact tier: clear rays with a wider t bound
  // model: rays whose object-space ray origin was read under an instance
  // whose world-to-object terms are large beside the result (a far
  // translation cancelled): |device - model| may reach the bound.
  std::vector<TBound> object_origin_bounds;
  // model, exact tier: the t bound of t_bounds carried into hit_position
  // (origin + t x direction): t's bound times the direction's largest
  // component, where that exceeds hit_position's own tolerance.
  std::vector<TBound> position_bounds;
  std::vector<UndefinedRay>
      undefined;  // model: rays whose behaviour is undefined (R-UB), one per ray
  // model, exact tier (R-AHIT-DUP): rays whose fields any-hit repetition may
  // change, and the counters it may move.
  std::vector<RepeatDependentRay> repeat_dependent;
  std::vector<std::string> repeat_counters;
  // model, exact tier: the least a counter that any-hit or intersection
  // programs count must reach on any device (model/counter_floors.cpp):
  // each program's leading counts, once for every candidate that every
  // legal order offers it on the clear launch rays; absent where none.
  std::map<std::string, uint64_t> counter_floors;
  // model, exact tier (R-ORDER-UNSPEC): candidate programs whose answers
  // depend on the order of more candidates than the model enumerates, each
  // named by its block and file:line (compare/order_dependent_verdict.h).
  std::vector<std::string> order_dependent;
  // model: restart_query statements that restart their query past
  // kMaxQueryRestarts times in one run of it, each named by its file:line
  // (compare/endless_restarts_verdict.h).
  std::vector<std::string> endless_restarts;
  // model as a legal device with a conservative AABB test (aabb-neighbours,
  // aabb-near): where the statements are written that reported (or
  // generated) inside the interval for a box the model's own ray misses, in
  // the order first made (mutate/not_portable_cause.cpp names the first).
  // Not saved in a bundle: only the legal devices' runs, in memory, have it.
  std::vector<SourceLoc> missed_box_reports;
  std::vector<std::string> validation_messages;  // validation-layer errors (device)
  // Device: what the device broke that only the device shows, each a Fail of
  // its rule: R-LIBRARY (library group handles that differ from the linked
  // pipeline's, vulkan/library_group_handles.h), R-AS-MEMORY (a build, update
  // or copy that wrote past the size the device reported, vulkan/memory_guards.h).
  std::vector<DeviceFinding> device_findings;
  // A case that expects its compiler to reject shaders (expect_rejected,
  // R-STAGE-INTERFACE) launches nothing: the device side names each shader
  // glslang refused for the forbidden interface; the model names every one
  // the case expects.
  std::vector<std::string> rejected;
  uint32_t library_handles_compared = 0;  // device: library group handles checked that way
  double seconds = 0.0;                   // wall time of the execution (setup + trace + read-back)
  StepCosts cost;                         // what each step of this side took (results/step_cost.h)
  std::string case_file;  // path of the case's YAML file (`rayspec compare` re-parses it)
  uint64_t case_hash =
      0;  // Case::source_hash of the case run: a saved bundle judged later must match it
};

// What a trace produced is the same: counters, records, image texels, the
// compiler's rejections and what only the device shows (results_queries.cpp).
bool sameOutput(const Results& a, const Results& b);
// The model's ambiguous rays by launch index.
std::map<uint32_t, const RayAmbiguity*> ambiguityByRay(const Results& model);

}  // namespace rayspec
