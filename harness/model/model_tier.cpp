// The tier names, in both builds (model/model_absent.cpp).
#include <stdexcept>

#include "model/model_engine.h"

namespace rayspec {

ModelTier parseModelTier(const std::string& name) {
  if (name == "fast") return ModelTier::Fast;
  if (name == "robust") return ModelTier::Robust;
  if (name == "exact") return ModelTier::Exact;
  throw std::invalid_argument("unknown model tier '" + name + "' (fast|robust|exact)");
}

const char* modelTierName(ModelTier t) {
  return nameOf(t);
}

}  // namespace rayspec
