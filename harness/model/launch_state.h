// The launch ray a Machine is on and what its launch rays leave behind:
// counters, the ray's record, ambiguous, bounded and undefined rays, and the
// first case error. Every part of the Machine writes here and nowhere else,
// so the exact tier's what-if runs can save and restore it (save, restore).
// The R-UB diagnoses are here too (launch_state_undefined.cpp): each marks
// the current launch ray once, with the first reason.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/legal_replays.h"
#include "model/model_sbt.h"
#include "model/model_shared.h"
#include "model/model_stage_env.h"
#include "results/results.h"

namespace rayspec {

// A stage's run counter in the record (raygen_runs .. callable_runs).
enum RunsField {
  kRunsRaygen,
  kRunsMiss,
  kRunsClosestHit,
  kRunsAnyHit,
  kRunsIntersection,
  kRunsCallable
};

struct LaunchState {
  LaunchState(const ModelShared& shared, const ModelSbt& sbt, uint32_t* records_in);

  // What the launch rays leave behind.
  std::vector<uint64_t> counters;
  std::vector<RayAmbiguity> ambiguous;
  std::vector<TBound> t_bounds;
  std::vector<TBound> object_origin_bounds;  // Results::object_origin_bounds
  std::vector<TBound> position_bounds;       // Results::position_bounds
  // R-UB: launch rays whose behaviour is undefined, the first reason each.
  // A what-if run of the exact tier may add one too: a legal path into
  // undefined behaviour makes the ray undefined.
  std::vector<UndefinedRay> undefined;
  std::string error;  // first case error (an unknown built-in or op)
  // Exact tier: the least each counter any-hit or intersection programs
  // count may reach on a device (Results::counter_floors), over the clear
  // launch rays; the launch ray's own so far in ray_floors (keepRayFloors).
  std::vector<uint64_t> floors, ray_floors;
  void keepRayFloors();
  // Exact tier, R-ORDER-UNSPEC: candidate programs whose answers depend on
  // the order past what the model enumerates (Results::order_dependent),
  // each named once (`place`, then the first ray's `what`).
  std::vector<std::string> order_dependent;
  void orderDependent(const std::string& place, const std::string& what) {
    for (const std::string& o : order_dependent)
      if (o.compare(0, place.size(), place) == 0) return;
    order_dependent.push_back(place + what);
  }
  // restart_query statements that restarted their query more than
  // kMaxQueryRestarts times in one run of it (Results::endless_restarts),
  // each named once (`place`, then the first ray's `what`).
  std::vector<std::string> endless_restarts;
  void endlessRestarts(const std::string& place, const std::string& what) {
    for (const std::string& o : endless_restarts)
      if (o.compare(0, place.size(), place) == 0) return;
    endless_restarts.push_back(place + what);
  }

  // A legal device with a conservative AABB test (aabb-neighbours,
  // aabb-near): the statements that reported (or generated) inside the
  // interval for a box the model's own ray misses, each once, in the order
  // first made (Results::missed_box_reports).
  std::vector<SourceLoc> missed_box_reports;
  void missedBoxReport(const SourceLoc& at) {
    for (const SourceLoc& o : missed_box_reports)
      if (o.file == at.file && o.line == at.line && o.column == at.column && o.field == at.field)
        return;
    missed_box_reports.push_back(at);
  }

  // The launch ray now.
  uint32_t* records = nullptr;  // ray i's record at records + i * recordWords()
  uint32_t* rec = nullptr;      // this launch ray's record
  uint32_t index = 0, x = 0, y = 0;
  std::array<uint32_t, 3> launch{};  // Rays::launchSize()
  bool ray_ambiguous = false;
  bool ray_undefined = false;
  // A legal answer of the launch ray hits a triangle it runs in the plane
  // of, at no one t (ModelCandidate::in_plane), where that t matters beyond
  // the fields its bound widens (TraceClassifier::inPlaneTMatters): the ray
  // keeps no replays.
  bool ray_t_free = false;
  bool repeated_any_hit = false;  // AnyHitRepeat::First: this launch ray repeated one
  uint32_t call_nesting = 0;      // callables running now (Pipeline::callableDepth)
  // A legal replay of this launch ray (legal_replays.h): which answer each
  // ambiguous trace takes; null on the model's own run.
  ReplayScript* replay = nullptr;

  // Starts launch ray i (its record, its flags cleared).
  void startRay(uint32_t i);
  void record(int field, const Val& v, ValueType t);
  void bumpRuns(int which) {  // kRuns* above
    if (rec) rec[runs_offset_[which]] += 1;
  }
  uint32_t runsOffset(int which) const { return runs_offset_[which]; }
  // any-hit runs on a primitive: its run count and its bit in any_hit_slots
  // (any_hit_repeats when set already; results/record_layout.h).
  void markAnyHit(const HitView& hv);
  void bump(const CountsOnly& k) {
    if (k.counters.size() == 1) {
      counters[k.counters[0]] += 1;
      return;
    }
    for (int i : k.counters) counters[i] += 1;
  }

  // What a sandbox keeps: the counters, the launch's record, the error, and
  // the launch ray's floors so far (a what-if run's nested queries count
  // none).
  struct Saved {
    std::vector<uint64_t> counters;
    std::vector<uint32_t> record;
    std::string error;
    std::vector<uint64_t> ray_floors;
  };
  Saved save() const;
  void restore(const Saved& s);

  // Undefined behaviour (R-UB), launch_state_undefined.cpp; the model then
  // goes on in the documented way of each caller.
  void markUndefined(UndefinedReason why, std::string what);
  // Non-finite origin or direction, NaN or negative tmin, tmax below tmin,
  // an illegal flag combination: true when the ray is undefined (it is then
  // traced as nothing: no candidate, a miss). `site`: the trace statement
  // (or raygen's `trace: {}` of the launch ray).
  bool checkRayParameters(const TraceRay& r, const CStmt* site, uint32_t depth);
  void hitRecordOutOfRange(uint32_t instance, uint32_t geometry, const TraceRay& r);
  void missRecordOutOfRange(const TraceRay& r);
  // A shader declaring the incoming payload type of location `shader_location`
  // reached by a trace whose payload has another type.
  // The shader is named `list`[index]`stage` ("pipeline.miss", 2, "").
  void checkPayloadType(const Payload& p, uint32_t shader_location, const char* list,
                        uint32_t index, const char* stage) {
    if (sh_.payload_types && !ray_undefined)
      payloadTypeDiffers(p, shader_location, list, index, stage);
  }
  // A callable declaring another incoming callable data type than the call passes.
  void callDataTypeDiffers(const CallData& d, uint32_t callable);
  void divisionByZero(const CExpr& e);
  // R-NULL-SHADERS: a shader of kind `flag` (a pipeline flag no_null_*) would
  // run from an all-zero SBT record of `region`: undefined when the pipeline
  // has that flag.
  void nullShader(uint32_t flag, const char* shader, const char* region, uint32_t record) {
    if ((sh_.c->pipeline.flags & flag) && !ray_undefined)
      nullShaderReached(flag, shader, region, record);
  }

 private:
  void payloadTypeDiffers(const Payload& p, uint32_t shader_location, const char* list,
                          uint32_t index, const char* stage);
  void nullShaderReached(uint32_t flag, const char* shader, const char* region, uint32_t record);

  const ModelShared& sh_;
  const ModelSbt& sbt_;
  uint32_t runs_offset_[6] = {};
  uint32_t slots_offset_ = 0, repeats_offset_ = 0;  // any_hit_slots, any_hit_repeats
};

}  // namespace rayspec
