#include "cli/limits_check.h"

#include <cstdio>

#include "report/baseline_gate.h"
#include "vulkan/required_limits.h"

namespace rayspec {

LimitsVerdict printLimitChecks(const DeviceInfo& d, const Baseline& baseline) {
  LimitsVerdict v;
  std::printf("        required limits (Vulkan specification, Limits chapter, Required Limits):\n");
  for (const LimitCheck& c : checkRequiredLimits(d)) {
    const bool listed = expectedStatus(baseline, c.caseName()) == Status::Fail;
    const char* verdict = !c.applies ? "NotSupported" : c.ok ? "Pass" : "Fail";
    std::string note;
    if (c.applies && !c.ok) {
      ++v.violations;
      ++(listed ? v.expected : v.unexpected);
      note = listed ? " (expected by the baseline)" : " (UNEXPECTED)";
    } else if (listed) {
      ++v.unexpected_passes;
      note = " (the baseline expects Fail: update it)";
    }
    std::printf("          %-12s %s: %llu, %s %s%s\n", verdict, c.caseName().c_str(),
                static_cast<unsigned long long>(c.value), c.requirement.c_str(),
                c.applies ? ("(" + c.structure + ")").c_str() : "(the device lacks it)",
                note.c_str());
  }
  return v;
}

}  // namespace rayspec
