// libFuzzer target: any bytes as a case file (or a sweep file) through the
// parser, the sweep expansion and the plan. Every malformed input must end in
// error messages: never a crash, a hang, a leak or undefined behaviour
// (the fuzz preset builds with AddressSanitizer and UndefinedBehaviorSanitizer).
#include <cstddef>
#include <cstdint>
#include <string>

#include "library/expand_sweep.h"
#include "parse/parse_case.h"
#include "plan/plan.h"

namespace {

void parseAndPlan(const std::string& text, const std::string& name) {
  const rayspec::ParseResult parsed = rayspec::parseCaseText(text, "fuzz.yaml", name);
  for (const rayspec::Error& e : parsed.errors) (void)e.format();
  if (!parsed.value) return;
  const rayspec::Plan plan = rayspec::derivePlan(*parsed.value);
  (void)plan.describe();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text.rfind("sweep:", 0) == 0 || text.find("\nsweep:") != std::string::npos) {
    const rayspec::SweepExpansion ex = rayspec::expandSweep(text, "fuzz.sweep.yaml", "fuzz/case");
    for (const rayspec::Error& e : ex.errors) (void)e.format();
    // A few variants are enough to reach the parser; a sweep may hold thousands.
    for (size_t i = 0; i < ex.variants.size() && i < 4; ++i)
      parseAndPlan(ex.variants[i].text, ex.variants[i].name);
    return 0;
  }
  parseAndPlan(text, "fuzz/case");
  return 0;
}
