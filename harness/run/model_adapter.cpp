#include "run/model_adapter.h"

namespace rayspec {

std::string ModelAdapter::description() const {
  return std::string("embree, ") + modelTierName(options_.tier) + " tier";
}

}  // namespace rayspec
