#include "results/results.h"

namespace rayspec {

bool sameOutput(const Results& a, const Results& b) {
  if (a.records != b.records || a.counters != b.counters || a.images.size() != b.images.size() ||
      a.rejected != b.rejected || a.device_findings != b.device_findings)
    return false;
  for (size_t i = 0; i < a.images.size(); ++i)
    if (a.images[i].texels != b.images[i].texels) return false;
  return true;
}

std::map<uint32_t, const RayAmbiguity*> ambiguityByRay(const Results& model) {
  std::map<uint32_t, const RayAmbiguity*> out;
  for (const RayAmbiguity& a : model.ambiguous) out[a.ray] = &a;
  return out;
}

}  // namespace rayspec
