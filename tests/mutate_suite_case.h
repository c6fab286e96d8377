// A library case mutated as `rayspec mutate` does, the model's own answers
// standing for the device (tests/mutate_*_test.cpp); with `through`, the
// case as a run --through that path sends it.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "metamorphic/feature_path.h"

#include "model/model_engine.h"
#include "mutate/mutate_case.h"
#include "suite_cases.h"

namespace rayspec {

// A library case, as a run --through `through` sends it (when given).
inline Case suiteCaseThrough(const std::string& name,
                             std::optional<FeaturePath> through = std::nullopt) {
  const std::vector<CaseFile> files = findCases(kSuiteCases, name);
  EXPECT_EQ(files.size(), 1u) << name;
  const ParseResult parsed = loadSuiteCase(files.at(0));
  EXPECT_TRUE(parsed.value) << name;
  Case c = *parsed.value;
  if (through) {
    Result<Case> sent = throughPath(c, *through);
    EXPECT_TRUE(sent) << name << ": " << (sent ? "" : sent.error().format());
    if (sent) c = std::move(*sent);
  }
  return c;
}

inline CaseMutation mutateSuiteCase(const std::string& name,
                                    std::optional<FeaturePath> through = std::nullopt) {
  const Case c = suiteCaseThrough(name, through);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, {});
  Results device = model;
  device.backend = "vulkan";
  return mutateCase(c, plan, device, model);
}

// The outcome of planted fault `fault` in a case's mutation; none if not judged.
inline const MutantOutcome* findPlanted(const CaseMutation& m, const std::string& fault) {
  for (const MutantOutcome& o : m.mutants)
    if (o.name == "planted:" + fault) return &o;
  return nullptr;
}

}  // namespace rayspec
