#include "fuzz/generator_features.h"

#include <utility>
#include <vector>

#include "run/library_support.h"
#include "vulkan/case_support.h"

namespace rayspec {
namespace {

// A device feature the generator can leave out: the DeviceInfo member whose
// row names it, and the GeneratorFeatures member that draws it.
struct Leavable {
  bool DeviceInfo::*device;
  bool GeneratorFeatures::*generator;
};
constexpr Leavable kLeavable[] = {
    {&DeviceInfo::ray_query, &GeneratorFeatures::ray_query},
    {&DeviceInfo::shader_int8, &GeneratorFeatures::shader_int8},
    {&DeviceInfo::shader_int16, &GeneratorFeatures::shader_int16},
    {&DeviceInfo::shader_int64, &GeneratorFeatures::shader_int64},
    {&DeviceInfo::shader_float16, &GeneratorFeatures::shader_float16},
    {&DeviceInfo::shader_float64, &GeneratorFeatures::shader_float64}};

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

bool allowsType(const GeneratorFeatures& features, ValueType t) {
  const bool DeviceInfo::*device = sizedTypeFeature(t);
  for (const Leavable& l : kLeavable)
    if (device && l.device == device) return features.*l.generator;
  return true;
}

std::string leftOutText(const GeneratorFeatures& features) {
  std::string text;
  for (const auto& [label, member] : leavable())
    if (!(features.*member)) text += (text.empty() ? "without " : ", ") + label;
  return text;
}

}  // namespace rayspec
