// The tier names, in both builds (model/model_absent.cpp).
#include "model/model_engine.h"

namespace rayspec {

std::optional<ModelTier> parseModelTier(const std::string& name) {
  return valueNamed<ModelTier>(name);
}

const char* modelTierName(ModelTier t) {
  return nameOf(t);
}

}  // namespace rayspec
