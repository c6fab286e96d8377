#include "program/stage_interface.h"

namespace rayspec {

std::optional<std::string> forbiddenInterface(Stage stage, BuiltinNeeds uses) {
  if (stage == Stage::Intersection && (uses & builtin_needs::InPayload)) return "rayPayloadInEXT";
  if (stage == Stage::Miss && (uses & builtin_needs::HitAttribute)) return "hitAttributeEXT";
  return std::nullopt;
}

}  // namespace rayspec
