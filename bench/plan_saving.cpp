// What the plan saves: one case run by the model with the plan as derived
// (only the effects, fields, counters and images the case asks for) and with
// every effect switched on (plan/plan.h everyEffectPlan: every Plan flag, every
// recordable field, an image of each), in one process, exact tier, all cores.
// The cases: model/mixed-scene-1024 (1M rays: triangles, spheres, any-hit) and
// watertight/shared-edges (81 rays), or the glob given in RAYSPEC_PLAN_CASES.
// Both runs must agree on the counters (checked). The machine is shared:
// --benchmark_repetitions=3 and compare medians.
#include <benchmark/benchmark.h>

#include <cstdio>
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
  Plan derived, every;
};

std::vector<PlannedCase>& cases() {
  static std::vector<PlannedCase> out = [] {
    std::vector<PlannedCase> v;
    const std::string dir = RAYSPEC_SOURCE_DIR "/cases";
    std::vector<std::string> globs = {"model/mixed-scene-1024", "watertight/shared-edges"};
    if (const char* g = std::getenv("RAYSPEC_PLAN_CASES")) globs = {g};
    for (const std::string& glob : globs)
      for (const CaseFile& f : findCases(dir, glob)) {
        ParseResult p = loadCase(f, dir);
        if (!p.value || !p.errors.empty()) continue;
        PlannedCase pc{*p.value, derivePlan(*p.value), everyEffectPlan(*p.value)};
        v.push_back(std::move(pc));
      }
    return v;
  }();
  return out;
}

void runPlan(benchmark::State& state, const PlannedCase& pc, bool every) {
  ModelOptions o;
  o.tier = ModelTier::Exact;
  const Plan& plan = every ? pc.every : pc.derived;
  Results r;
  for (auto _ : state) {
    r = runOnModel(pc.c, plan, o);
    benchmark::DoNotOptimize(r.records.data());
  }
  if (!r.ok()) state.SkipWithError(r.statusText().c_str());
  // The plan may drop work, never change an answer: the counters agree.
  if (every && r.counters != runOnModel(pc.c, pc.derived, o).counters)
    state.SkipWithError("the counters differ between the derived plan and every effect");
  state.counters["rays_per_second"] = benchmark::Counter(
      double(pc.c.rays.rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["record_fields"] = static_cast<double>(plan.record_fields.size());
  state.counters["images"] = static_cast<double>(plan.images.size());
}

}  // namespace
}  // namespace rayspec

int main(int argc, char** argv) {
  for (const rayspec::PlannedCase& pc : rayspec::cases())
    for (bool every : {false, true})
      benchmark::RegisterBenchmark(
          ("BM_Plan/" + std::string(every ? "every-effect/" : "derived/") + pc.c.name).c_str(),
          [&pc, every](benchmark::State& s) { rayspec::runPlan(s, pc, every); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
