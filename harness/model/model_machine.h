// One worker of the model: interprets the stage programs of a case for the
// rays it is given, traces through the Embree scene, and writes counters,
// per-ray records and ambiguities. One Machine per thread.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case/case.h"
#include "model/model_faults.h"
#include "model/model_program.h"
#include "model/model_scene.h"
#include "model/model_trace_context.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

struct Payload {
  std::array<float, 4> color{};
  uint32_t value = 0;
  uint32_t depth = 0;
  uint32_t location = 0;  // the trace's payload location (its type: Pipeline::payload_words)
  std::array<uint32_t, kMaxPayloadWords> words{};
};

struct CallData {
  std::array<float, 4> color{};
  std::array<float, 3> position{}, normal{};
  uint32_t value = 0;
  uint32_t location = 0;  // the call's data location (its type: Pipeline::call_data_words)
  std::array<uint32_t, kMaxCallDataWords> words{};
};

struct TraceRay {
  Vec3 origin{}, direction{};
  float tmin = 0, tmax = 0;
  uint32_t flags = 0, cull_mask = 0xFF, sbt_offset = 0, sbt_stride = 1, miss = 0;
  uint32_t tlas = 0;  // the top level traversed
};

// The trace of a launch's own ray (`trace: {}` in raygen).
inline TraceRay launchRay(const Ray& base) {
  TraceRay r;
  r.origin = base.origin;
  r.direction = base.direction;
  r.tmin = base.tmin;
  r.tmax = base.tmax;
  r.flags = base.flags;
  r.cull_mask = base.cull_mask;
  r.sbt_offset = base.sbt_offset;
  r.sbt_stride = base.sbt_stride;
  r.miss = base.miss;
  return r;
}

// Built-ins of a hit or candidate.
struct HitView {
  uint32_t primitive = 0, instance = 0, custom_index = 0, geometry = 0, hit_kind = 0;
  float t = 0, b1 = 0, b2 = 0;
  Vec3 object_origin{}, object_direction{};
  Vec3 aabb_min{}, aabb_max{};
  // A triangle hit's vertices in object space (geometry transform applied):
  // the vertex_position<i> built-ins; nullptr for a box.
  const std::array<Vec3, 3>* vertices = nullptr;
  // The words a report gave the hit attribute (attribute.word<i>).
  std::array<uint32_t, kMaxAttributeWords> words{};
};

struct Traversal;

// Exact tier, R-PREC: a decision of an intersection program that float
// rounding may flip on a device (reason "shader-arith"): the n-th (ordinal)
// sphere_hit (kind 0) or report interval test (kind 1) of candidate `cand`'s
// intersection program, and the value it took (or is forced to take).
struct ShaderDecision {
  size_t cand = 0;
  uint8_t kind = 0;
  uint32_t ordinal = 0;
  bool value = false;
};

// The hit a traversal committed.
struct Committed {
  bool valid = false;
  double t = 0;
  uint32_t instance = 0, geometry = 0, primitive = 0, kind = 0;
  float b1 = 0, b2 = 0;
  // Exact tier: bound on a device's t beyond the model's (a sphere root's
  // rounding, a triangle's frame error).
  double t_err = 0;
  std::array<uint32_t, kMaxAttributeWords> words{};  // a report's attribute words
};

// How one what-if run of the exact tier decides (Machine::sandbox):
// candidates forced to be a hit (1) or not (0), -1 the model's own decision;
// the candidate that wins every tie (prefer) or is processed first (first),
// -1 none; an intersection program's decision flipped. `actual`: the trace's
// own run, no what-if.
struct WhatIf {
  bool actual = false;
  std::vector<int8_t> force;  // empty: none forced
  long prefer = -1, first = -1;
  std::optional<ShaderDecision> shader;
};
struct WhatIfAnswer {
  Committed best;
  WhatIf how;
};

struct StageEnv {
  Stage stage = Stage::Raygen;
  const std::vector<uint32_t>* record_data = nullptr;
  Payload* payload = nullptr;  // incoming payload, or raygen's last trace payload
  Payload child;               // last nested trace (closest-hit, miss)
  CallData* call = nullptr;    // incoming callable data
  CallData callee;             // after this stage's last call
  const TraceRay* ray = nullptr;
  const HitView* hit = nullptr;
  float tmax_view = 0;
  uint32_t depth = 0;
  Traversal* traversal = nullptr;  // intersection (report) and any-hit
  std::vector<Val> locals;         // the frame's local variables (program/locals.h slots)
};

// How a statement ends: go on, ignore / terminate (any-hit), or leave a
// repeat (Break), an iteration (Next) or a function (Return).
enum class Flow { Continue, Ignore, Terminate, Break, Next, Return };

enum RunsField {
  kRunsRaygen,
  kRunsMiss,
  kRunsClosestHit,
  kRunsAnyHit,
  kRunsIntersection,
  kRunsCallable
};

struct ModelShared {
  const Case* c = nullptr;
  const Plan* plan = nullptr;
  const ModelScene* scene = nullptr;
  const CPipeline* programs = nullptr;  // compiled once per run
  bool direct = false;                  // rtcIntersect1's own closest hit (no filters)
  // Decided once per run from what the programs read: a direct hit needs its
  // facing only for hit_kind, its object-space ray only for object_ray_*.
  bool need_facing = true, need_object_ray = true;
  bool raygen_traces_launch_ray = false;  // raygen is exactly `trace: {}`
  bool payload_types = false;             // pipeline.payloads declares several locations
  ModelFaults faults;  // test only: the planted faults' hook (model/model_faults.h)
  AnyHitRepeat any_hit_repeat = AnyHitRepeat::None;  // R-AHIT-DUP (model_engine.h)
  // Some candidate may be undefined (a hit record beyond the region, a NaN
  // triangle): Machine::checkCandidates looks at every candidate.
  bool check_candidates = true;
};

// Cache-line aligned: each worker thread writes its own Machine, never a line
// another worker reads (no false sharing between neighbouring allocations).
class alignas(64) Machine {
 public:
  Machine(const ModelShared& shared, uint32_t* records);
  // Runs raygen for launch indices [begin, end) (records for ray i start at
  // records + i * words).
  void runRays(uint32_t begin, uint32_t end);

  std::vector<uint64_t> counters;
  std::vector<RayAmbiguity> ambiguous;
  std::vector<TBound> t_bounds;
  // R-UB: launch rays whose behaviour is undefined, the first reason each
  // (model_machine_undefined.cpp). A what-if run of the exact tier may add
  // one too: a legal path into undefined behaviour makes the ray undefined.
  std::vector<UndefinedRay> undefined;
  std::string error;  // first case error (an unknown built-in or op)

 private:
  friend struct Traversal;
  friend class TraceClassifier;  // model_exact_tier.cpp: classifyTrace's steps
  Val eval(const CExpr& e, StageEnv& env);
  Val builtin(const CExpr& e, StageEnv& env);
  Val rayBuiltin(const CExpr& e, const StageEnv& env) const;
  Val hitBuiltin(const CExpr& e, const StageEnv& env) const;
  Val dataBuiltin(const CExpr& e, StageEnv& env);
  // Word index % words of a data array indexed by a value (payload_word ..
  // callee_word, store: payload.words / call.words); null where the stage has
  // no such data or the type no words.
  static uint32_t* dataWord(WordArray which, uint32_t words, uint32_t index, StageEnv& env);
  // shader_record.NAME: its words in the record data (pipeline.sbt.record_layout).
  static Val recordMember(const CExpr& e, const StageEnv& env);
  Val vertexPosition(const HitView& hv, int i) const;
  Val op(const CExpr& e, StageEnv& env);
  // The ops op() runs before evaluating arguments (spheres, shader record
  // words, short-circuit and/or); false for any other op.
  bool opOnDemand(const CExpr& e, StageEnv& env, Val& r);
  // add sub mul div min max on evaluated arguments.
  Val arithmetic(const CExpr& e, const Val* a);
  Flow exec(const CProgram& p, StageEnv& env);
  Flow execStmt(const CStmt& s, StageEnv& env);
  void execSet(const CStmt& s, StageEnv& env);      // set payload / set call data
  Flow execControl(const CStmt& s, StageEnv& env);  // let .. return (model_control_flow.cpp)
  Flow execRepeat(const CStmt& s, StageEnv& env);
  Flow execSwitch(const CStmt& s, StageEnv& env);
  Flow execInvoke(const CStmt& s, StageEnv& env);
  void loseLocals(StageEnv& env) const;
  Val transformBuiltin(const HitView& hv, int k) const;
  void execCall(const CStmt& s, StageEnv& env);   // executeCallableEXT
  void execTrace(const CStmt& s, StageEnv& env);  // traceRayEXT
  Payload startPayload(const CStmt& s, StageEnv& env);
  TraceRay tracedRay(const CStmt& s, StageEnv& env);
  void record(int field, const Val& v, ValueType t);
  void bumpRuns(int which) {  // kRuns* above
    if (rec_) rec_[runs_offset_[which]] += 1;
  }
  // any-hit runs on a primitive: its run count and its bit in any_hit_slots
  // (any_hit_repeats when set already; results/record_layout.h).
  void markAnyHit(const HitView& hv);
  // Runs any-hit `p` for a candidate, marked, and again (AnyHitRepeat,
  // R-AHIT-DUP) where its geometry lacks NO_DUPLICATE_ANY_HIT_INVOCATION and
  // the first run did not terminate: the second run's answer stands.
  Flow runAnyHit(const CProgram& p, StageEnv& a, const HitView& hv, uint32_t geometry_flags);
  // `site`: the trace statement (or raygen's `trace: {}` of the launch ray),
  // named when the trace is undefined.
  // model_traversal.cpp; `payload` is what the trace starts with
  Payload trace(const TraceRay& r, uint32_t depth, const CStmt* site, Payload payload = {});
  Committed directHit(const TraceRay& r, uint32_t flags);
  Committed traverse(const TraceRay& r, uint32_t flags, uint32_t depth, Payload& payload);
  void shade(const TraceRay& r, uint32_t flags, uint32_t depth, const Committed& best,
             Payload& payload);
  void decide(Traversal& tr, const std::vector<ModelCandidate>& cands, const int8_t* force,
              Payload& payload);
  // decide's steps: an AABB candidate's intersection program; whether a
  // triangle candidate's t counts.
  void runIntersection(Traversal& tr, const ModelCandidate& cand, size_t k, bool opaque,
                       const SbtRecord* rec, const CHitGroup* grp);
  bool triangleInside(const Traversal& tr, const ModelCandidate& cand, size_t k,
                      const int8_t* force) const;
  // One decision of the trace as `how` says, on `payload` (decideAs), and the
  // same in a sandbox: counters, record and error restored, the payload a
  // copy of the trace's incoming one (sandbox).
  // What a sandbox keeps: the counters, the launch's record and the error.
  struct MachineState {
    std::vector<uint64_t> counters;
    std::vector<uint32_t> record;
    std::string error;
  };
  MachineState saveState() const;
  void restoreState(const MachineState& s);
  Committed decideAs(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                     const WhatIf& how, Payload& payload);
  Committed sandbox(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                    const WhatIf& how, const Payload& payload_in);
  // sphere_hit in an intersection program: the model's value, or the forced
  // one of a what-if run; notes an unsure decision (model_exact_tier.cpp).
  bool sphereHitDecision(StageEnv& env, bool model_value, float disc);
  // Exact tier: marks the current ray ambiguous when this trace's answer could
  // differ on a device, with the legal answers (model_exact_tier.cpp).
  // Returns how to decide the trace as a legal device that takes another of
  // its answers (ModelFaults::legal_answer, pass_between_edges), if asked.
  std::optional<WhatIf> classifyTrace(Traversal& tr, const std::vector<ModelCandidate>& cands,
                                      const std::vector<std::pair<size_t, double>>& reports,
                                      const std::vector<ShaderDecision>& shader_unsure,
                                      const Payload& payload_in);
  bool anyHitMayTerminate(const Traversal& tr, const std::vector<ModelCandidate>& cands) const;
  // `leaks`: the answers of devices passing between the triangles of a
  // shared edge or vertex (no triangle of a group of two or more hit).
  std::vector<WhatIfAnswer> whatIf(const Traversal& actual,
                                   const std::vector<ModelCandidate>& cands,
                                   const std::vector<size_t>& unsure, const Payload& payload_in,
                                   std::vector<WhatIfAnswer>* leaks);
  void runRaygen();
  // Raygen is `trace: {}` and traces take Embree's closest hit: the chunk's
  // rays are traced first, then shaded (model_fast_path.cpp).
  void runLaunchRaysDirect(uint32_t begin, uint32_t end);
  // runLaunchRaysDirect's way for a launch ray that is not only counted: as
  // trace() does, with the ray's launch state and Embree's answer.
  const CountsOnly* countedMiss(const TraceRay& r0) const;
  void shadeLaunchRay(uint32_t i, const Ray& ray, uint32_t flags, const RTCRayHit& rh, bool hit,
                      uint32_t* rec);
  void bump(const CountsOnly& k) {
    if (k.counters.size() == 1) {
      counters[k.counters[0]] += 1;
      return;
    }
    for (int i : k.counters) counters[i] += 1;
  }
  Flow report(const CStmt& s, StageEnv& env);  // model_traversal.cpp
  // Whether a reported t becomes a candidate hit (report's first step).
  bool reportInside(const CStmt& s, StageEnv& env, Traversal& tr, float t);
  // R-PREC: how far a device's sphere root (a report's t) may lie from the
  // model's, for the hit h.
  double sphereRootError(const CStmt& s, const HitView& h, const StageEnv& env) const;
  void callCallable(uint32_t index, CallData& data, uint32_t depth, const CStmt& site);
  const SbtRecord* hitRecord(uint32_t instance, uint32_t geometry, const TraceRay& r) const;
  uint64_t hitRecordIndex(uint32_t instance, uint32_t geometry, const TraceRay& r) const;

  // Undefined behaviour (R-UB), model_machine_undefined.cpp. Each notes the
  // current launch ray once, with the first reason; the model then goes on
  // in the documented way of each caller.
  void markUndefined(UndefinedReason why, std::string what);
  bool rayUndefined() const { return ray_undefined_; }
  // Non-finite origin or direction, NaN or negative tmin, tmax below tmin,
  // an illegal flag combination: true when the ray is undefined (it is then
  // traced as nothing: no candidate, a miss).
  bool checkRayParameters(const TraceRay& r, const CStmt* site, uint32_t depth);
  // Every candidate a device may need the hit record of (an AABB, a
  // non-opaque triangle) with the record beyond the hit region, and a
  // triangle with NaN in Y or Z whose region the ray crosses.
  void checkCandidates(const Traversal& tr, const std::vector<ModelCandidate>& cands);
  void hitRecordOutOfRange(uint32_t instance, uint32_t geometry, const TraceRay& r);
  void missRecordOutOfRange(const TraceRay& r);
  // A shader declaring the incoming payload type of location `shader_location`
  // reached by a trace whose payload has another type.
  // The shader is named `list`[index]`stage` ("pipeline.miss", 2, "").
  void checkPayloadType(const Payload& p, uint32_t shader_location, const char* list,
                        uint32_t index, const char* stage) {
    if (sh_.payload_types && !ray_undefined_)
      payloadTypeDiffers(p, shader_location, list, index, stage);
  }
  // A callable declaring another incoming callable data type than the call passes.
  void callDataTypeDiffers(const CallData& d, uint32_t callable);
  void payloadTypeDiffers(const Payload& p, uint32_t shader_location, const char* list,
                          uint32_t index, const char* stage);
  void divisionByZero(const CExpr& e);
  // R-NULL-SHADERS: a shader of kind `flag` (a pipeline flag no_null_*) would
  // run from an all-zero SBT record of `region`: undefined when the pipeline
  // has that flag.
  void nullShader(uint32_t flag, const char* shader, const char* region, uint32_t record) {
    if ((sh_.c->pipeline.flags & flag) && !ray_undefined_)
      nullShaderReached(flag, shader, region, record);
  }
  void nullShaderReached(uint32_t flag, const char* shader, const char* region, uint32_t record);

  const ModelShared& sh_;
  uint32_t* records_;
  uint32_t* rec_ = nullptr;  // this launch's record
  uint32_t index_ = 0, x_ = 0, y_ = 0;
  std::array<uint32_t, 3> launch_{};  // Rays::launchSize()
  bool ray_ambiguous_ = false;
  bool ray_undefined_ = false;
  bool repeated_any_hit_ = false;  // AnyHitRepeat::First: this launch ray repeated one
  uint32_t call_nesting_ = 0;      // callables running now (Pipeline::callableDepth)
  std::vector<SbtRecord> default_miss_, default_hit_, default_callable_;
  std::vector<std::vector<ModelCandidate>> cand_pool_;
  uint32_t runs_offset_[6] = {};
  uint32_t slots_offset_ = 0, repeats_offset_ = 0;  // any_hit_slots, any_hit_repeats
};

}  // namespace rayspec
