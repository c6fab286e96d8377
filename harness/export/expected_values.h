// What the model expects of a case's counters and fields, as the judge
// holds a device to them (compare/compare_counters.cpp,
// compare/compare_records.cpp): the one source of the C and the Amber
// exports' expectations.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "compare/counter_modes.h"
#include "plan/plan.h"
#include "results/record_layout.h"
#include "results/results.h"

namespace rayspec {

// One counter (plan.counters order, its index in the counter buffer) with
// the range the judge allows: the model's count, as far as the legal answers
// of ambiguous rays move it, opened by its mode and never below the model's
// floor; hi is UINT64_MAX where unbounded above.
struct ExpectedCounter {
  std::string name;
  std::string rule;  // the rule a mismatch names
  uint64_t lo = 0, hi = 0;
  CounterMode how = CounterMode::Exact;
};
std::vector<ExpectedCounter> expectedCounters(const Case& c, const Plan& plan,
                                              const Results& model);

// The rules a case checks, as an export's header lists them ("(none)").
std::string caseRulesText(const Case& c);

// The rule a field's mismatch names, as the judge names it.
std::string expectedFieldRule(const Case& c, const RecordField& f);

}  // namespace rayspec
