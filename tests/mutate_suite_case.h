// A library case mutated as `rayspec mutate` does, the model's own answers
// standing for the device (tests/mutate_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/model_engine.h"
#include "mutate/mutate_case.h"
#include "suite_cases.h"

namespace rayspec {

inline CaseMutation mutateSuiteCase(const std::string& name) {
  const std::vector<CaseFile> files = findCases(kSuiteCases, name);
  EXPECT_EQ(files.size(), 1u) << name;
  const ParseResult parsed = loadSuiteCase(files.at(0));
  EXPECT_TRUE(parsed.value) << name;
  const Case& c = *parsed.value;
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, {});
  Results device = model;
  device.backend = "vulkan";
  return mutateCase(c, plan, device, model);
}

}  // namespace rayspec
