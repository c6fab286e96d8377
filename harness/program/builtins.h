// The built-in values a stage program may read, with their type, the stages
// that may read them and their meaning (program/builtin_table.h, the one
// list). Both backends give each name the meaning written there.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "program/builtin_table.h"
#include "program/program.h"

namespace rayspec {

// Bit set of stages (1u << int(Stage)).
using StageMask = unsigned;
constexpr StageMask stageBit(Stage s) {
  return 1u << static_cast<unsigned>(s);
}
constexpr StageMask kAllStages = 0x3F;

// One-letter stage bits for the built-in, operator and statement tables.
namespace stage_letters {
constexpr StageMask R = stageBit(Stage::Raygen);
constexpr StageMask M = stageBit(Stage::Miss);
constexpr StageMask C = stageBit(Stage::ClosestHit);
constexpr StageMask A = stageBit(Stage::AnyHit);
constexpr StageMask I = stageBit(Stage::Intersection);
constexpr StageMask K = stageBit(Stage::Callable);
}  // namespace stage_letters

// What reading a built-in needs beyond its value (builtin_table.h's needs
// column), read by the model (model/model_engine.cpp) and the plan
// (plan/plan.cpp), so that a new row cannot be forgotten there.
using BuiltinNeeds = uint8_t;
namespace builtin_needs {
constexpr BuiltinNeeds NoNeeds = 0;
constexpr BuiltinNeeds Facing = 1;         // the hit's facing (the model's fast path computes it)
constexpr BuiltinNeeds Triangles = 2;      // the model keeps each triangle's vertices
constexpr BuiltinNeeds ObjectRay = 4;      // the hit's object-space ray
constexpr BuiltinNeeds PositionFetch = 8;  // VK_KHR_ray_tracing_position_fetch (and the vertices)
constexpr BuiltinNeeds CullMask = 16;      // VK_KHR_ray_tracing_maintenance1's gl_CullMaskEXT
constexpr BuiltinNeeds BoxData = 32;       // the primitive's AABB (the scene data buffer)
}  // namespace builtin_needs

struct BuiltinInfo {
  const char* name;
  ValueType type;
  StageMask stages;
  BuiltinNeeds needs;
  const char* glsl;       // the GLSL a stage reads; nullptr: the emitter spells it
  const char* ray_query;  // inlined in raygen ($c: committed); nullptr: word<i>, hit, vertices
  const char* meaning;    // one line, shown by `rayspec show` and in errors
};

// Every built-in, in the order of program/builtin_table.h: kBi<Id>.
enum Builtin : uint8_t {
#define RAYSPEC_BUILTIN_ID(id, ...) kBi##id,
  RAYSPEC_BUILTINS(RAYSPEC_BUILTIN_ID)
#undef RAYSPEC_BUILTIN_ID
      kBiCount,
  kBiUnknown = 0xFF
};
static_assert(kBiCount < kBiUnknown, "a Builtin is stored in a byte");

// The indexed families, counted from their first row.
constexpr int kBiTransformEnd = kBiWorldToObject3x4_2 + 1;
static_assert(kBiVertex2 == kBiVertex0 + 2, "vertex_position0..2 in order");
static_assert(kBiWorldToObject0 == kBiObjectToWorld0 + 7 &&
                  kBiTransformEnd == kBiObjectToWorld0 + 14,
              "object_to_world0..3, _3x4_0..2, then world_to_object's, in order");

// The ray query getters: candidate.* then committed.*, the hit rows (t ..
// world_to_object3, vertex_position0..2) of each in the same order, then query.*.
constexpr int kBiQueryHitRows = kBiQCandType - kBiQCandT;
static_assert(kBiQueryHitRows == 21 && kBiQCommittedT == kBiQCandT + kBiQueryHitRows + 2 &&
                  kBiQCommittedType == kBiQCommittedT + kBiQueryHitRows &&
                  kBiQWorldDirection == kBiQCommittedType + 4,
              "candidate.*, committed.* and query.* rows in order");
constexpr bool isQueryBuiltin(int b) {
  return b >= kBiQCandT && b <= kBiQWorldDirection;
}

// candidate.vertex_position<i> or committed.vertex_position<i> (position
// fetch through a ray query).
bool isQueryVertexPosition(const std::string& name);
// vertex_position<i> (gl_HitTriangleVertexPositionsEXT in a hit stage).
bool isHitVertexPosition(const std::string& name);

// The table of program/builtin_table.h, indexed by Builtin.
const std::vector<BuiltinInfo>& builtins();
// The row a name reads: payload.word3 is payload.word<i>'s. nullptr: none.
const BuiltinInfo* findBuiltin(const std::string& name);
// Its Builtin (kBiUnknown for nullptr).
Builtin builtinId(const BuiltinInfo* info);
// Its ray query spelling for the candidate (committed false) or the committed
// intersection; "" where it has none (BuiltinInfo::ray_query).
std::string rayQuerySpelling(const BuiltinInfo& info, bool committed);

}  // namespace rayspec
