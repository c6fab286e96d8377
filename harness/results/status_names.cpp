// What the typed statuses and reasons of results/results.h say beyond their names.
#include "results/results.h"

namespace rayspec {
std::string Results::statusText() const {
  if (status == SideStatus::Ok) return "ok";
  return std::string(sideStatusName(status)) + ": " + status_detail;
}

const char* ruleForAmbiguity(AmbiguityReason r) {
#define RAYSPEC_AMBIGUITY_RULE(id, name, rule) rule,
  static constexpr const char* kRules[] = {RAYSPEC_AMBIGUITY_REASONS(RAYSPEC_AMBIGUITY_RULE)};
#undef RAYSPEC_AMBIGUITY_RULE
  return kRules[static_cast<size_t>(r)];
}

}  // namespace rayspec
