#include "fuzz/generator_features.h"

#include <utility>
#include <vector>

#include "run/library_support.h"

namespace rayspec {
namespace {

// A device feature the generator can leave out: the DeviceInfo member whose
// row names it, and the GeneratorFeatures member that draws it.
struct Leavable {
  bool DeviceInfo::*device;
  bool GeneratorFeatures::*generator;
};
constexpr Leavable kLeavable[] = {{&DeviceInfo::ray_query, &GeneratorFeatures::ray_query}};

// The leavable features by their rows' labels, in the rows' order.
std::vector<std::pair<std::string, bool GeneratorFeatures::*>> leavable() {
  std::vector<std::pair<std::string, bool GeneratorFeatures::*>> out;
  for (const auto& [label, member] : featureRows())
    for (const Leavable& l : kLeavable)
      if (member == l.device) out.emplace_back(label, l.generator);
  return out;
}

}  // namespace

std::string leavableFeatureNames() {
  std::string names;
  for (const auto& [label, member] : leavable()) names += (names.empty() ? "" : ", ") + label;
  return names;
}

Result<void> leaveOut(GeneratorFeatures& features, const std::string& name) {
  for (const auto& [label, member] : leavable())
    if (label == name) {
      features.*member = false;
      return {};
    }
  return errorMessage("unknown feature '" + name + "': the generator leaves out only " +
                      leavableFeatureNames() +
                      " (as `rayspec devices` names the features a device lacks)");
}

std::string leftOutText(const GeneratorFeatures& features) {
  std::string text;
  for (const auto& [label, member] : leavable())
    if (!(features.*member)) text += (text.empty() ? "without " : ", ") + label;
  return text;
}

}  // namespace rayspec
