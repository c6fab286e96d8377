// R-POSITION-FETCH broken: a device whose gl_HitTriangleVertexPositionsEXT
// gives the vertices in world space (through the instance transform) instead
// of object space (the model's test-only hook, model/model_faults.h).
#include <algorithm>

#include "fault/fault_impl.h"

namespace rayspec {

std::string positionFetchWorldSpace(Case& c, ModelOptions& o) {
  o.faults.position_fetch_world_space = true;
  const bool moved =
      std::any_of(c.scene.instances.begin(), c.scene.instances.end(),
                  [](const Instance& i) { return i.blas && i.transform != kIdentity; });
  return moved ? "vertex positions are read in world space" : "";
}

}  // namespace rayspec
