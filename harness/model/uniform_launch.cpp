#include "model/uniform_launch.h"

namespace rayspec {

bool launchIdRead(const CPipeline& programs) {
  return programs.reads(kBiLaunchX) || programs.reads(kBiLaunchY) || programs.reads(kBiLaunchZ);
}

bool launchUniform(const Case& c, const Plan& plan, const CPipeline& programs) {
  return c.rays.same && !plan.records && c.outputs.images.empty() && !launchIdRead(programs);
}

bool oneIdStandsForAll(const Results& one_id) {
  return one_id.ambiguous.empty() && one_id.undefined.empty();
}

void scaleToLaunch(Results& one_id, uint64_t ids) {
  for (auto& [name, n] : one_id.counters) n *= ids;
  for (auto& [name, n] : one_id.counter_floors) n *= ids;
}

}  // namespace rayspec
