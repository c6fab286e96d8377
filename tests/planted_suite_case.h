// A library case judged with a planted fault, the model's own answers
// (perfectDevice) standing for the device: the steps the fault tests of
// suite cases share (tests/fault_*_test.cpp).
#pragma once

#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "plan/plan.h"
#include "suite_cases.h"

namespace rayspec {

// A library case, its plan and the model's results.
struct SuiteModelRun {
  Case c;
  Plan plan;
  Results model;
};

// The case of `f` parsed, planned and run on the model; none, and a failed
// expectation naming it, when it does not parse or the model fails.
inline std::optional<SuiteModelRun> suiteModelRun(const CaseFile& f) {
  ParseResult parsed = loadSuiteCase(f);
  EXPECT_TRUE(parsed.value) << f.name << ": " << parsed.errors.at(0).format();
  if (!parsed.value) return std::nullopt;
  SuiteModelRun run{std::move(*parsed.value), {}, {}};
  run.plan = derivePlan(run.c);
  run.model = runOnModel(run.c, run.plan, ModelOptions{});
  EXPECT_TRUE(run.model.ok()) << f.name << ": " << run.model.statusText();
  if (!run.model.ok()) return std::nullopt;
  return run;
}

// The same for the library case of that name.
inline std::optional<SuiteModelRun> suiteModelRun(const std::string& name) {
  const std::optional<CaseFile> f = suiteCase(name);
  EXPECT_TRUE(f) << name;
  if (!f) return std::nullopt;
  return suiteModelRun(*f);
}

// The verdict on the model's own answers, no fault planted.
inline Status perfectStatus(const SuiteModelRun& run) {
  return compareResults(run.c, run.plan, perfectDevice(run.c, run.model), run.model).status;
}

// The planted fault's result on the model's own answers, and the verdict.
struct PlantedVerdict {
  FaultResult fault;
  Verdict verdict;
};

inline PlantedVerdict plantOnModel(const SuiteModelRun& run, const std::string& fault) {
  Results device = perfectDevice(run.c, run.model);
  PlantedVerdict p;
  p.fault = plantFault(fault, run.c, run.plan, device, run.model);
  p.verdict = compareResults(run.c, run.plan, device, run.model);
  return p;
}

// The fault planted in library case `name`, whose model answers must pass.
inline PlantedVerdict plantOnSuiteCase(const std::string& name, const std::string& fault) {
  const std::optional<SuiteModelRun> run = suiteModelRun(name);
  if (!run) return {};
  EXPECT_EQ(perfectStatus(*run), Status::Pass) << name;
  return plantOnModel(*run, fault);
}

}  // namespace rayspec
