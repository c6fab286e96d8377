// The model's run of a library case (tests/model_ray_query*_test.cpp), and
// one record field down its rays.
#pragma once

#include <cstdint>
#include <vector>

#include "model_support.h"
#include "suite_cases.h"

namespace rayspec::model_test {

inline Results runSuiteCase(const char* name, ModelTier tier, const ModelFaults& faults = {}) {
  const Case c = suiteCaseFile(name);
  ModelOptions o;
  o.tier = tier;
  o.threads = 1;
  o.faults = faults;
  return runOnModel(c, derivePlan(c), o);
}

using V = std::vector<uint32_t>;

inline V column(const Results& r, const char* field, uint32_t rays) {
  V v;
  for (uint32_t i = 0; i < rays; ++i) v.push_back(word(r, i, field));
  return v;
}

}  // namespace rayspec::model_test
