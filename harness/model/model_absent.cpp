// The model of a run-only build (RAYSPEC_WITH_MODEL=OFF, preset `device`):
// none. CMake compiles this file and model_tier.cpp in place of the Embree
// model, so such a binary links neither Embree nor TBB. The run loop runs the
// device side only there (run/run_only.h); were the model asked anyway, the
// answer is NotSupported, never a reference to pass against.
#include "model/model_engine.h"

namespace rayspec {

bool modelInThisBuild() {
  return false;
}

Results runOnModel(const Case& c, const Plan&, const ModelOptions& opt) {
  Results r;
  r.case_name = c.name;
  r.backend = "model";
  r.device = std::string("none-") + modelTierName(opt.tier);
  r.setStatus(SideStatus::NotSupported,
              "this run-only build has no model (RAYSPEC_WITH_MODEL=OFF)");
  return r;
}

}  // namespace rayspec
