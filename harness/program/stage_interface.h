// The two "cannot" clauses of a stage's interface (R-STAGE-INTERFACE): an
// intersection shader has no payload (rayPayloadInEXT is not allowed there)
// and a miss shader has no hit attribute (nor is hitAttributeEXT). A program
// that reads or writes them is a case error, unless the case expects the
// compiler to reject that shader (expect_rejected): then the checker notes
// the use, the GLSL declares what the program uses, and glslang must refuse
// the declaration.
#pragma once

#include <optional>
#include <string>

#include "program/builtins.h"

namespace rayspec {

// The GLSL qualifier a use that needs `uses` (a built-in's needs,
// program/builtin_table.h; InPayload for a payload write) needs in `stage`
// that the stage cannot declare: "rayPayloadInEXT" or "hitAttributeEXT";
// nullopt when it is no such use.
std::optional<std::string> forbiddenInterface(Stage stage, BuiltinNeeds uses);

// A use of a forbidden interface the checker let through (expect_rejected).
struct InterfaceUse {
  std::string qualifier;  // "rayPayloadInEXT" / "hitAttributeEXT"
  std::string what;       // "payload.value", "payload: {...}", "barycentrics"
  SourceLoc loc;
};

}  // namespace rayspec
