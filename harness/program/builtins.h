// The built-in values a stage program may read, with their type, the stages
// that may read them and their meaning (program/builtin_table.h, the one
// list). Both backends give each name the meaning written there.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "program/builtin_table.h"
#include "program/payload_words.h"
#include "program/program.h"

namespace rayspec {

// Bit set of stages (1u << int(Stage)).
using StageMask = unsigned;
constexpr StageMask stageBit(Stage s) {
  return 1u << static_cast<unsigned>(s);
}
constexpr StageMask kAllStages = 0x3F;
// The stages of a mask by name, in the Stage enum's order: "raygen, miss".
std::string stageList(StageMask mask);

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
// column), read by the model (model/model_engine.cpp), the plan
// (plan/plan.cpp), the GLSL (glsl/stage_uses.cpp) and the stage interface's
// checks (program/stage_interface.cpp), so that a new row cannot be
// forgotten there.
using BuiltinNeeds = uint16_t;
namespace builtin_needs {
constexpr BuiltinNeeds NoNeeds = 0;
constexpr BuiltinNeeds Facing = 1;          // the hit's facing (the model's fast path computes it)
constexpr BuiltinNeeds Triangles = 2;       // the model keeps each triangle's vertices
constexpr BuiltinNeeds ObjectRay = 4;       // the hit's object-space ray
constexpr BuiltinNeeds PositionFetch = 8;   // VK_KHR_ray_tracing_position_fetch (and the vertices)
constexpr BuiltinNeeds CullMask = 16;       // VK_KHR_ray_tracing_maintenance1's gl_CullMaskEXT
constexpr BuiltinNeeds BoxData = 32;        // the primitive's AABB (the scene data buffer)
constexpr BuiltinNeeds HitAttribute = 64;   // the hit attribute (hitAttributeEXT; none in miss)
constexpr BuiltinNeeds InPayload = 128;     // the incoming payload (rayPayloadInEXT; none in
                                            // intersection), in raygen the last trace's
constexpr BuiltinNeeds ChildPayload = 256;  // the payload of this stage's last trace
constexpr BuiltinNeeds CallData = 512;      // the incoming callable data (callable)
constexpr BuiltinNeeds CalleeData = 1024;   // the callable data of this stage's last call
constexpr BuiltinNeeds HitObject = 2048;    // the stage's hit object (VK_NV_ray_tracing_
                                            // invocation_reorder's hitObjectNV)
// Data carried between stages (payloads, callable data), not a value of the API.
constexpr BuiltinNeeds CarriedData = InPayload | ChildPayload | CallData | CalleeData;
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

// The indexed families, counted from their first row.
constexpr int kBiTransformEnd = kBiWorldToObject3x4_2 + 1;
static_assert(kBiVertex2 == kBiVertex0 + 2, "vertex_position0..2 in order");
static_assert(kBiWorldToObject0 == kBiObjectToWorld0 + 7 &&
                  kBiTransformEnd == kBiObjectToWorld0 + 14,
              "object_to_world0..3, _3x4_0..2, then world_to_object's, in order");
// The instance matrices of a hit stage (object_to_world*, world_to_object*).
constexpr bool isInstanceTransform(int b) {
  return b >= kBiObjectToWorld0 && b < kBiTransformEnd;
}

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
// candidate.* (the current candidate's getters).
constexpr bool isCandidateGetter(int b) {
  return b >= kBiQCandT && b < kBiQCommittedT;
}
// committed.* (the committed intersection's getters).
constexpr bool isCommittedGetter(int b) {
  return b >= kBiQCommittedT && b <= kBiQCommittedType;
}
// vertex_position<i> (gl_HitTriangleVertexPositionsEXT in a hit stage).
constexpr bool isHitVertexPosition(int b) {
  return b >= kBiVertex0 && b <= kBiVertex2;
}
// candidate.vertex_position<i> or committed.vertex_position<i> (position
// fetch through a ray query).
constexpr bool isQueryVertexPosition(int b) {
  return (b >= kBiQCandVertex0 && b <= kBiQCandVertex2) ||
         (b >= kBiQCommittedVertex0 && b <= kBiQCommittedVertex2);
}
// The rows that stand for a family of names by index: payload.word<i>,
// child.word<i>, attribute.word<i>, call.word<i>, callee.word<i>.
constexpr bool isWordFamily(int b) {
  return b == kBiPayloadWord || b == kBiChildWord || b == kBiAttributeWord || b == kBiCallWord ||
         b == kBiCalleeWord;
}
// The rows that stand for a family of names by sized type (the index is the
// ValueType): payload.<type>, child.<type>, call.<type>, callee.<type>,
// attribute.<type> (program/payload_words.h SizedMembers). An expression of
// one has the member's type.
constexpr bool isSizedFamily(int b) {
  return b == kBiPayloadSized || b == kBiChildSized || b == kBiCallSized || b == kBiCalleeSized ||
         b == kBiAttributeSized;
}
// The data a sized family row reads (nullopt for another row).
std::optional<SizedData> sizedDataOf(Builtin b);
// The data a word<i> read indexes: payload.word<i> the payload's words,
// child.word<i> the child's, call.word<i> and callee.word<i> the callable
// data's; nullopt for another row (attribute.word<i> included).
std::optional<WordArray> wordArrayOf(Builtin b);

// The table of program/builtin_table.h, indexed by Builtin.
const std::vector<BuiltinInfo>& builtins();
// A built-in's needs (builtin_table.h's column); NoNeeds for kBiUnknown.
BuiltinNeeds builtinNeeds(Builtin b);

// A name a program writes, resolved: its row and, in a word<i> family, i
// (payload.word3: kBiPayloadWord, 3). The parser's one resolution of a
// built-in's name.
struct BuiltinName {
  Builtin id = kBiUnknown;
  uint32_t word = 0;
};
// nullopt for a name no row reads (a family's own "payload.word<i>" included).
std::optional<BuiltinName> builtinNamed(const std::string& name);
// The name a program writes for row `id` (with i = word in a word<i> family).
std::string builtinSpelling(Builtin id, uint32_t word = 0);
// The row a name reads: payload.word3 is payload.word<i>'s. nullptr: none.
const BuiltinInfo* findBuiltin(const std::string& name);
// Its Builtin (kBiUnknown for nullptr).
Builtin builtinId(const BuiltinInfo* info);
// The type a read of row `id` has: its row's, a sized family's member's own.
ValueType builtinType(Builtin id, uint32_t word = 0);

// A read of built-in `id` (word i of a word<i> family), typed as its row
// (what a fault or a rewrite builds); setBuiltin makes e such a read. Both
// write the id, the word, the spelling (Expr::name) and the type together,
// so that they never disagree (setBuiltin drops what e held as another kind:
// its op, arguments and literal).
Expr builtinExpr(Builtin id, const SourceLoc& loc, uint32_t word = 0);
void setBuiltin(Expr& e, Builtin id, uint32_t word = 0);
// A read of the built-in `name` spells (builtinNamed); for a name no row
// reads, kBiUnknown under that name (the type checker's "unknown built-in").
Expr builtinExpr(const std::string& name, const SourceLoc& loc = {});
// Whether e reads built-in `id`.
inline bool isBuiltin(const Expr& e, Builtin id) {
  return e.kind == Expr::Kind::Builtin && e.builtin == id;
}
// Its ray query spelling for the candidate (committed false) or the committed
// intersection; "" where it has none (BuiltinInfo::ray_query).
std::string rayQuerySpelling(const BuiltinInfo& info, bool committed);

}  // namespace rayspec
