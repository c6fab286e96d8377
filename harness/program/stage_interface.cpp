#include "program/stage_interface.h"

#include "program/payload_words.h"

namespace rayspec {

std::optional<std::string> forbiddenInterface(Stage stage, const std::string& name) {
  if (stage == Stage::Intersection) {
    const bool payload = name.empty() || name == "payload.color" || name == "payload.value" ||
                         (payloadWordBuiltin(name) && !payloadWordBuiltin(name)->child);
    if (payload) return "rayPayloadInEXT";
  }
  if (stage == Stage::Miss && (name == "barycentrics" || attributeWordBuiltin(name)))
    return "hitAttributeEXT";
  return std::nullopt;
}

}  // namespace rayspec
