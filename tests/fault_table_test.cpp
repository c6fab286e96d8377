// The fault table is complete: every fault `--plant-fault` takes has a
// description and stands for a rule (fault/rule_faults.h), but for the faults
// of the run itself; `rayspec faults` prints both from these tables.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "fault/planted_fault.h"
#include "fault/rule_faults.h"

namespace rayspec {
namespace {

// Crashes, hangs and failed Vulkan calls test how a run reports a broken
// device, not a rule of the specification (a refused pipeline stands for
// R-EMPTY-LAYOUT, whose CTS test asks only that the pipeline is made).
const std::set<std::string> kRunFaults = {"crash", "crash-once",  "crash-if-reused",
                                          "hang",  "device-lost", "out-of-device-memory"};

TEST(FaultTable, EveryFaultHasOneLineSayingWhatItBreaks) {
  std::set<std::string> names;
  for (const FaultInfo& f : faultTable()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name << " twice";
    EXPECT_GE(f.breaks.size(), 20u) << f.name << ": '" << f.breaks << "'";
    EXPECT_EQ(f.breaks.find('\n'), std::string::npos) << f.name;
    EXPECT_NE(std::string(faultKindText(f.kind)), "") << f.name;
  }
  EXPECT_GE(names.size(), 110u);
}

TEST(FaultTable, EveryFaultButTheRunsOwnStandsForARule) {
  for (const FaultInfo& f : faultTable()) {
    const RulesOfFault r = rulesOfFault(f.name);
    const bool any = !r.breaks.empty() || !r.allows.empty();
    EXPECT_EQ(any, !kRunFaults.count(f.name)) << f.name;
    // A variation a rule allows is marked legal in its description.
    EXPECT_EQ(!r.allows.empty(), f.breaks.rfind("legal:", 0) == 0) << f.name;
  }
  EXPECT_EQ(rulesOfFault("inactive-revived").breaks, (std::vector<std::string>{"R-INACTIVE"}));
  EXPECT_EQ(rulesOfFault("reverse-order").allows,
            (std::vector<std::string>{"R-ORDER-UNSPEC", "R-TOFH"}));
  EXPECT_EQ(rulesOfFault("stride-ignored").breaks, (std::vector<std::string>{"R-AS-BUILD"}))
      << "a live device's fault, in RuleFaults::live";
  EXPECT_TRUE(rulesOfFault("no-such-fault").breaks.empty());
}

}  // namespace
}  // namespace rayspec
