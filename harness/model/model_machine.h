// One worker of the model: runs the launch rays it is given, one at a time,
// through its parts, and keeps what they leave behind. One Machine per thread.
//   LaunchState       the launch ray now, counters, records, R-UB marks
//   ModelSbt          the shader binding table's regions
//   ModelBuiltins     what a built-in reads
//   StageInterpreter  the stage programs
//   HitProtocol       the any-hit / intersection protocol of a candidate
//   ModelTracer       traceRayEXT: enumerate, decide, exact tier, shade
// The parts hold references to each other (a trace runs programs, a program
// traces), all into this Machine, so a Machine is neither copied nor moved.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/alike_rays.h"
#include "model/hit_protocol.h"
#include "model/launch_state.h"
#include "model/model_builtins.h"
#include "model/model_sbt.h"
#include "model/model_shared.h"
#include "model/model_tracer.h"
#include "model/stage_interpreter.h"

namespace rayspec {

// Cache-line aligned: each worker thread writes its own Machine, never a line
// another worker reads (no false sharing between neighbouring allocations).
class alignas(64) Machine {
 public:
  Machine(const ModelShared& shared, uint32_t* records);
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;
  // Runs raygen for launch indices [begin, end) (records for ray i start at
  // records + i * words); a ray alike the one traced last is not traced
  // again (alike_rays.h).
  void runRays(uint32_t begin, uint32_t end);
  // What the rays run so far left behind (counters, ambiguous, bounded and
  // undefined rays, the first case error).
  const LaunchState& state() const { return state_; }

 private:
  // Launch ray i, and in the exact tier each legal answer of it where it is
  // ambiguous (replayLegalAnswers).
  void runWithReplays(uint32_t i);
  // Raygen for launch ray i.
  void runRay(uint32_t i);
  // Exact tier: each legal answer of ambiguous launch ray i replayed through
  // the ray, into its RayAmbiguity (legal_replays.cpp), after the model's own
  // run (`script`: its choices, all 0); the ray's own record, counters and
  // error stay the model's own.
  void replayLegalAnswers(uint32_t i, size_t ambiguity, ReplayScript& script);
  LegalReplay replayOutcome(const LaunchState::Saved& own) const;
  // One scripted run of launch ray i from the counters before it: its outcome.
  LegalReplay replayRun(uint32_t i, const LaunchState::Saved& own);
  // The leak pass, or with `doubles` the double pass (legal_replays.h),
  // after the legal one left `legal`: the distinct outcomes of the runs that
  // take a leak answer (a double hit), none of `legal`; none where one's
  // path is undefined, pins a t, or past the bounds.
  std::vector<LegalReplay> replayExtra(uint32_t i, const LaunchState::Saved& own,
                                       const std::vector<LegalReplay>& legal, bool doubles,
                                       ReplayScript& script);

  const ModelShared& sh_;
  ModelSbt sbt_;
  LaunchState state_;
  ModelBuiltins builtins_;
  StageInterpreter interp_;
  HitProtocol hits_;
  ModelTracer tracer_;
  std::vector<uint64_t> counters_before_;  // the counters before the launch ray now
  ReplayScript script_;                    // the launch ray's replays (legal_replays.h)
  AlikeRays alike_;                        // the launch ray traced last (alike_rays.h)
};

}  // namespace rayspec
