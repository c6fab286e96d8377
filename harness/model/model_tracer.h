// traceRayEXT in the model: Embree enumerates a trace's candidates, the
// tracer decides them in order (model_engine.h), the exact tier checks
// whether a device could answer otherwise (model_exact_tier.cpp), then
// closest-hit or miss runs (model_traversal.cpp); a trace with nothing to
// decide takes Embree's own closest hit (model_fast_path.cpp). The programs
// a candidate runs go through HitProtocol, closest-hit and miss through the
// StageInterpreter.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "model/launch_state.h"
#include "model/model_sbt.h"
#include "model/model_shared.h"
#include "model/model_stage_env.h"
#include "model/model_trace_context.h"
#include "model/model_what_if.h"

namespace rayspec {

struct Traversal;
struct LeadReport;
struct QueryRun;
struct OrderOutcome;
class StageInterpreter;
class HitProtocol;

class ModelTracer {
 public:
  ModelTracer(const ModelShared& shared, LaunchState& state, const ModelSbt& sbt,
              StageInterpreter& interp, HitProtocol& hits)
      : sh_(shared), st_(state), sbt_(sbt), interp_(interp), hits_(hits) {}
  // One trace; `site`: the trace statement (or raygen's `trace: {}` of the
  // launch ray), named when the trace is undefined; `payload` is what the
  // trace starts with.
  Payload trace(const TraceRay& r, uint32_t depth, const CStmt* site, Payload payload = {});
  // hitObjectTraceRayNV (model/hit_object_trace.cpp): the trace's traversal
  // (any-hit and intersection programs run), its committed hit or miss, ray
  // and SBT record kept in `into`, no closest-hit or miss run; the payload as
  // traversal left it.
  Payload traceIntoHitObject(const TraceRay& r, uint32_t depth, const CStmt* site, Payload payload,
                             HitObjectState& into);
  // hitObjectExecuteShaderNV: the closest-hit or miss the hit object's trace
  // would have run, with that hit's built-ins, on `payload`; nothing for an
  // empty one.
  void executeHitObject(const HitObjectState& h, Payload& payload);
  // hitObjectRecordHitNV / hitObjectRecordHitWithIndexNV: a hit of `r` on
  // `hit`'s instance, geometry and primitive, its hit kind and attributes
  // (hit.b1, b2) as given, t the ray's tmax; every other built-in derived from
  // the instance (model/hit_object_record.cpp). `index`: the record given;
  // else the instance's offset and the ray's sbt_offset and sbt_stride pick it.
  // A hit outside the scene leaves the ray undefined (R-UB) and `into` empty.
  void recordHit(const TraceRay& r, const HitView& hit, std::optional<uint32_t> index,
                 uint32_t depth, const CStmt* site, HitObjectState& into);
  // The record data `h` names (its sbt_index in the hit or miss region).
  void noteRecordData(HitObjectState& h) const;
  // The hit record a recorded hit runs: `index`, or the instance's SBT offset
  // plus r's sbt_offset and geometry times sbt_stride (R-SBT-HIT).
  uint64_t recordedHitIndex(const HitView& h, const TraceRay& r,
                            std::optional<uint32_t> index) const;
  // Raygen is `trace: {}` and traces take Embree's closest hit: the launch
  // rays [begin, end) are traced and shaded in one pass (model_fast_path.cpp).
  void runLaunchRaysDirect(uint32_t begin, uint32_t end);
  // A ray_query's traversal (model_query.cpp): q.ray traversed, its
  // candidates decided by its blocks, what stays committed in q.committed.
  void rayQuery(QueryRun& q, const CStmt* site);

 private:
  friend class TraceClassifier;  // trace_classifier.cpp: classifyTrace's steps
  Committed directHit(const TraceRay& r, uint32_t flags);
  // trace's first steps: the flags the pipeline adds, the ray's parameters
  // checked, the committed hit (directHit or traverse); `flags` gets the flags.
  Committed committedHit(const TraceRay& r, uint32_t depth, const CStmt* site, Payload& payload,
                         uint32_t& flags);
  Committed traverse(const TraceRay& r, uint32_t flags, uint32_t depth, Payload& payload,
                     QueryRun* query = nullptr);
  // traverse's steps: the ray's candidates in the order they are decided
  // (none for a ray Embree cannot trace: validRay), from the pool of its
  // depth or query level; and R-UB where a legal answer of this trace (the
  // ray ambiguous) has its hit or miss record beyond its region.
  std::vector<ModelCandidate>* candidatesOf(const TraceRay& r, uint32_t flags, uint32_t depth,
                                            const QueryRun* query);
  void checkLegalAnswerRecords(const TraceRay& r, uint32_t flags);
  // decide() for a ray query (model_query.cpp): the candidate blocks decide,
  // opaque triangles commit unoffered (R-RQ-CANDIDATES).
  void decideQuery(Traversal& tr, const std::vector<ModelCandidate>& cands, const int8_t* force);
  // R-MISS-XOR-CHIT: closest-hit or miss for the committed hit; a hit
  // object's hit runs the record of its `hit_index`.
  void shade(const TraceRay& r, uint32_t flags, uint32_t depth, const Committed& best,
             Payload& payload, std::optional<uint64_t> hit_index = std::nullopt);
  void decide(Traversal& tr, const std::vector<ModelCandidate>& cands, const int8_t* force,
              Payload& payload);
  // The candidate decided at position `pos` (R-TOFH what-if: `tr.first`
  // ahead of all others, the rest in order; an order what-if: `tr.order`'s) and its opacity, or
  // nullopt when the ray's cull-opaque flags skip it: decide's and decideQuery's first step.
  struct OrderedCandidate {
    size_t k;
    bool opaque;
  };
  std::optional<OrderedCandidate> candidateAt(const Traversal& tr,
                                              const std::vector<ModelCandidate>& cands,
                                              size_t pos) const;
  // Whether a box candidate is offered (decide's step): as a what-if run
  // forces it, else unless the model's ray misses it (ModelCandidate::
  // outside), where only a legal device offering such boxes offers it.
  bool boxOffered(const ModelCandidate& cand, size_t k, const int8_t* force) const;
  // Whether a triangle candidate's t counts (decide's step).
  bool triangleInside(const Traversal& tr, const ModelCandidate& cand, size_t k,
                      const int8_t* force) const;
  // R-UB: every candidate a device may need the hit record of (an AABB, a
  // non-opaque triangle) with the record beyond the hit region, and a
  // triangle with NaN in Y or Z whose region the ray crosses.
  void checkCandidates(const Traversal& tr, const std::vector<ModelCandidate>& cands);
  // One decision of the trace as `how` says, on `payload` (decideAs), and the
  // same in a sandbox: the launch state restored, the payload a copy of the
  // trace's incoming one (sandbox).
  // `noted`, when given, gets the run's intersection-program decisions that
  // rounding may flip (as the actual run notes them: Traversal::shader_unsure).
  // `reports`, when given, gets its intersection programs' reports
  // (Traversal::reports).
  Committed decideAs(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                     const WhatIf& how, Payload& payload,
                     std::vector<ShaderDecision>* noted = nullptr,
                     std::vector<std::pair<size_t, double>>* reports = nullptr);
  // `left`, when given, gets what the run leaves behind (the exact tier's orders).
  Committed sandbox(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                    const WhatIf& how, const Payload& payload_in, OrderOutcome* left = nullptr,
                    std::vector<ShaderDecision>* noted = nullptr,
                    std::vector<std::pair<size_t, double>>* reports = nullptr);
  // The digest of what a decision left behind (Committed::effect): `best`,
  // the payload, the launch state's record and counters, a query's frame.
  uint64_t effectOf(const Committed& best, const Payload& payload, const QueryRun* query);
  // Exact tier: marks the current ray ambiguous when this trace's answer could
  // differ on a device, with the legal answers (model_exact_tier.cpp).
  // Returns how to decide the trace as a legal device that takes another of
  // its answers (ModelFaultSeam::answerTaken), if asked.
  std::optional<WhatIf> classifyTrace(Traversal& tr, const std::vector<ModelCandidate>& cands,
                                      const std::vector<std::pair<size_t, double>>& reports,
                                      const std::vector<ShaderDecision>& shader_unsure,
                                      const Payload& payload_in);
  // A legal replay's trace that an earlier run of the same choices
  // classified (legal_replays.h): `chosen` as its script says, and true; false
  // where the trace is to be classified.
  bool replayKnownTrace(std::optional<WhatIf>& chosen);
  bool anyHitMayTerminate(const Traversal& tr, const std::vector<ModelCandidate>& cands) const;
  // Exact tier: what this trace's clear candidates must count on any device
  // into LaunchState::ray_floors (counter_floors.cpp), with its steps.
  void countFloors(const Traversal& tr, const std::vector<ModelCandidate>& cands,
                   const std::vector<LeadReport>& leads);
  bool floorsHold(const Traversal& tr, const std::vector<ModelCandidate>& cands) const;
  double floorEnd(const Traversal& tr) const;
  // `leaks`: the answers of devices passing between the triangles of a
  // shared edge or vertex (no triangle of a group of two or more hit).
  std::vector<WhatIfAnswer> whatIf(const Traversal& actual,
                                   const std::vector<ModelCandidate>& cands,
                                   const std::vector<size_t>& unsure, const Payload& payload_in,
                                   std::vector<WhatIfAnswer>* leaks);
  // runLaunchRaysDirect's way for a launch ray that is not only counted: as
  // trace() does, with the ray's launch state and Embree's answer.
  const CountsOnly* countedMiss(const TraceRay& r0) const;
  // runLaunchRaysDirect's steps: the launch ray's closest hit (R-UB
  // diagnosed); and, for a launch ray traced as the first one is, whether
  // its closest-hit or miss only counts (CountsOnly), which is then counted
  // in `q`, in a batch while the hit group stays the same (flushCounts adds
  // a batch to the counters).
  struct LaunchCounts {
    uint32_t last_instance = ~0u, last_geometry = ~0u;
    const CountsOnly* hit_counts = nullptr;
    const CountsOnly* miss_counts = nullptr;
    uint64_t hit_pending = 0, miss_pending = 0;
    uint32_t runs_hit = 0, runs_miss = 0;  // the run counts' words in a record
  };
  RTCRayHit launchClosestHit(uint32_t i, const Ray& ray, uint32_t flags, RTCScene top,
                             RTCIntersectContext& ctx);
  bool countedAlone(const RTCRayHit& rh, bool hit, const TraceRay& r0, LaunchCounts& q,
                    uint32_t* rec);
  void flushCounts(const CountsOnly* k, uint64_t& n);
  void shadeLaunchRay(uint32_t i, const Ray& ray, uint32_t flags, const RTCRayHit& rh, bool hit,
                      uint32_t* rec);

  void clobberCaller(const TraceRay& r, const Committed& best);  // a planted fault

  const ModelShared& sh_;
  LaunchState& st_;
  const ModelSbt& sbt_;
  StageInterpreter& interp_;
  HitProtocol& hits_;
  std::vector<std::vector<ModelCandidate>> cand_pool_;  // per trace depth
  // Per ray query nesting level; fixed, so that a nested query's candidates
  // never move the enclosing query's.
  std::array<std::vector<ModelCandidate>, kMaxQueryNesting> query_pool_;
  // The hit of the closest-hit running now (nullptr: none, or a miss): the
  // planted fault nested_trace_clobbers_hit overwrites it with a nested hit.
  HitView* shading_hit_ = nullptr;
  std::string effect_bytes_;  // effectOf's bytes, kept to reuse their memory
};

}  // namespace rayspec
