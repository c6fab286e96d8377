// One worker of the model: interprets the stage programs of a case for the
// rays it is given, traces through the Embree scene, and writes counters,
// per-ray records and ambiguities. One Machine per thread.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "model/model_scene.h"
#include "model/model_trace_context.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

struct Payload {
  std::array<float, 4> color{};
  uint32_t value = 0;
  uint32_t depth = 0;
};

struct CallData {
  std::array<float, 4> color{};
  std::array<float, 3> position{}, normal{};
  uint32_t value = 0;
};

struct Val {
  std::array<float, 4> f{};
  uint32_t u = 0;
  bool b = false;
};

struct TraceRay {
  Vec3 origin{}, direction{};
  float tmin = 0, tmax = 0;
  uint32_t flags = 0, cull_mask = 0xFF, sbt_offset = 0, sbt_stride = 1, miss = 0;
};

// Built-ins of a hit or candidate.
struct HitView {
  uint32_t primitive = 0, instance = 0, custom_index = 0, geometry = 0, hit_kind = 0;
  float t = 0, b1 = 0, b2 = 0;
  Vec3 object_origin{}, object_direction{};
  Vec3 aabb_min{}, aabb_max{};
};

struct Traversal;

struct StageEnv {
  Stage stage = Stage::Raygen;
  const std::vector<uint32_t>* record_data = nullptr;
  Payload* payload = nullptr;   // incoming payload, or raygen's last trace payload
  Payload child;                // last nested trace (closest-hit, miss)
  CallData* call = nullptr;     // incoming callable data
  CallData callee;              // after this stage's last call
  const TraceRay* ray = nullptr;
  const HitView* hit = nullptr;
  float tmax_view = 0;
  uint32_t depth = 0;
  Traversal* traversal = nullptr;  // intersection (report) and any-hit
};

enum class Flow { Continue, Ignore, Terminate };

enum RunsField { kRunsRaygen, kRunsMiss, kRunsClosestHit, kRunsAnyHit, kRunsIntersection, kRunsCallable };

struct ModelShared {
  const Case* c = nullptr;
  const Plan* plan = nullptr;
  const ModelScene* scene = nullptr;
  bool direct = false;  // rtcIntersect1's own closest hit (no filters)
  std::vector<int> counter_index_of_stmt_unused;
};

class Machine {
 public:
  Machine(const ModelShared& shared, uint32_t* records);
  // Runs raygen for launch index i (records for it start at records + i * words).
  void runRay(uint32_t index);

  std::vector<uint64_t> counters;
  std::vector<RayAmbiguity> ambiguous;
  std::string error;  // first case error (e.g. recursion deeper than allowed)

 private:
  friend struct Traversal;
  Val eval(const Expr& e, StageEnv& env);
  Val builtin(const std::string& name, StageEnv& env);
  Val op(const Expr& e, StageEnv& env);
  Flow exec(const Program& p, StageEnv& env);
  Flow execStmt(const Stmt& s, StageEnv& env);
  void record(const std::string& field, const Val& v, ValueType t);
  void bumpRuns(int which);  // kRuns* below
  int cachedId(const std::string* key, int kind);  // builtin / field / counter index, by address
  Payload trace(const TraceRay& r, uint32_t depth);
  Flow report(const Stmt& s, StageEnv& env);  // model_trace.cpp
  void callCallable(uint32_t index, CallData& data, uint32_t depth);
  const SbtRecord* hitRecord(uint32_t instance, uint32_t geometry, const TraceRay& r) const;

  const ModelShared& sh_;
  uint32_t* records_;
  uint32_t* rec_ = nullptr;  // this launch's record
  uint32_t index_ = 0, x_ = 0, y_ = 0;
  bool ray_ambiguous_ = false;
  std::vector<SbtRecord> default_miss_, default_hit_, default_callable_;
  std::vector<std::vector<ModelCandidate>> cand_pool_;
  uint32_t runs_offset_[6] = {};
  struct IdSlot { const std::string* key = nullptr; int kind = 0; int id = -1; };
  std::vector<IdSlot> id_cache_ = std::vector<IdSlot>(1024);
};

}  // namespace rayspec
