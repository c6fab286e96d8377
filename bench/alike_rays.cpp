// Launch rays alike, traced once (model/alike_rays.h) against every ray
// traced (ModelOptions::trace_each_ray), in one process, exact tier, all
// cores. The case: cts-amber/basic2/without-micromap-flags (20,736 rays alike,
// each a tie of four boxes the exact tier replays), or the glob given in
// RAYSPEC_ALIKE_CASES. Both runs must agree on the counters, the records and
// the ambiguous rays (checked). The machine is shared:
// --benchmark_repetitions=3 and compare medians.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

struct PlannedCase {
  Case c;
  Plan plan;
};

std::vector<PlannedCase>& cases() {
  static std::vector<PlannedCase> out = [] {
    std::vector<PlannedCase> v;
    const std::string dir = RAYSPEC_SOURCE_DIR "/cases";
    std::string glob = "cts-amber/basic2/without-micromap-flags";
    if (const char* g = std::getenv("RAYSPEC_ALIKE_CASES")) glob = g;
    for (const CaseFile& f : findCases(dir, glob)) {
      ParseResult p = loadCase(f, dir);
      if (!p.value || !p.errors.empty()) continue;
      v.push_back({*p.value, derivePlan(*p.value)});
    }
    return v;
  }();
  return out;
}

Results runOnce(const PlannedCase& pc, bool trace_each_ray) {
  ModelOptions o;
  o.tier = ModelTier::Exact;
  o.trace_each_ray = trace_each_ray;
  return runOnModel(pc.c, pc.plan, o);
}

// What the judge reads of both runs agrees (the ambiguous rays by ray and
// candidate count; the unit tests compare every field).
bool agree(const Results& a, const Results& b) {
  if (a.counters != b.counters || a.counter_floors != b.counter_floors ||
      a.records.size() != b.records.size() || a.ambiguous.size() != b.ambiguous.size())
    return false;
  for (size_t k = 0; k < a.records.size(); ++k)
    if (a.records[k] != b.records[k]) return false;
  for (size_t k = 0; k < a.ambiguous.size(); ++k)
    if (a.ambiguous[k].ray != b.ambiguous[k].ray ||
        a.ambiguous[k].candidates.size() != b.ambiguous[k].candidates.size() ||
        a.ambiguous[k].replays != b.ambiguous[k].replays)
      return false;
  return true;
}

void runAlike(benchmark::State& state, const PlannedCase& pc, bool trace_each_ray) {
  Results r;
  for (auto _ : state) {
    r = runOnce(pc, trace_each_ray);
    benchmark::DoNotOptimize(r.records.data());
  }
  if (!r.ok()) state.SkipWithError(r.statusText().c_str());
  if (!trace_each_ray && !agree(r, runOnce(pc, true)))
    state.SkipWithError("the memo's results differ from tracing every ray");
  state.counters["rays_per_second"] = benchmark::Counter(
      double(pc.c.rays.launchRays()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["ambiguous"] = static_cast<double>(r.ambiguous.size());
}

}  // namespace
}  // namespace rayspec

int main(int argc, char** argv) {
  for (const rayspec::PlannedCase& pc : rayspec::cases())
    for (bool each : {true, false})
      benchmark::RegisterBenchmark(
          ("BM_Alike/" + std::string(each ? "each-ray/" : "alike-once/") + pc.c.name).c_str(),
          [&pc, each](benchmark::State& s) { rayspec::runAlike(s, pc, each); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
