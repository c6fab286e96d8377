#include "vulkan/required_limits.h"

#include <bit>
#include <string_view>

namespace rayspec {
namespace {

// The word that names the limits footnote 9 of the table speaks of.
constexpr std::string_view kUpdateAfterBind = "UpdateAfterBind";

std::string requirementText(LimitBound bound, uint64_t required, bool power_of_two) {
  std::string text = bound == LimitBound::Min   ? "at least "
                     : bound == LimitBound::Max ? "at most "
                                                : "exactly ";
  text += std::to_string(required);
  if (power_of_two) text += ", a power of two";
  return text;
}

bool meets(LimitBound bound, uint64_t value, uint64_t required, bool power_of_two) {
  if (power_of_two && !std::has_single_bit(value)) return false;
  switch (bound) {
    case LimitBound::Min:
      return value >= required;
    case LimitBound::Max:
      return value <= required;
    case LimitBound::Exact:
      return value == required;
  }
  return false;
}

// Whether the device has what makes the limit apply: the extension of its
// structure, and for the UpdateAfterBind limits the feature (footnote 9 of
// the table: without it the limit may be zero).
bool limitApplies(const DeviceInfo& d, const std::string& name, const char* structure) {
  if (std::string_view(structure) == kPipelineProperties) return d.ray_tracing_extension;
  if (name.find(kUpdateAfterBind) != std::string::npos)
    return d.acceleration_structure_extension && d.acceleration_structure_update_after_bind;
  return d.acceleration_structure_extension;
}

}  // namespace

std::vector<LimitCheck> checkRequiredLimits(const DeviceInfo& d) {
  std::vector<LimitCheck> checks;
#define RAYSPEC_CHECK_LIMIT(member, name, bound, required, power_of_two, structure) \
  {                                                                                 \
    LimitCheck c{name, structure, static_cast<uint64_t>(d.member),                  \
                 requirementText(LimitBound::bound, required, power_of_two)};       \
    c.applies = limitApplies(d, name, structure);                                   \
    c.ok = !c.applies || meets(LimitBound::bound, c.value, required, power_of_two); \
    checks.push_back(std::move(c));                                                 \
  }
  RAYSPEC_REQUIRED_LIMITS(RAYSPEC_CHECK_LIMIT)
#undef RAYSPEC_CHECK_LIMIT
  // Footnote 9: where the feature is there, an UpdateAfterBind limit is at
  // least its ordinary counterpart too.
  for (LimitCheck& c : checks) {
    const size_t at = c.name.find(kUpdateAfterBind);
    if (at == std::string::npos || !c.applies) continue;
    const std::string ordinary = c.name.substr(0, at) + c.name.substr(at + kUpdateAfterBind.size());
    for (const LimitCheck& o : checks)
      if (o.name == ordinary && c.value < o.value) {
        c.ok = false;
        c.requirement += " and at least " + ordinary + " (" + std::to_string(o.value) + ")";
      }
  }
  return checks;
}

}  // namespace rayspec
