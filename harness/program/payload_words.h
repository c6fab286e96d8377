// The extra uint words of a payload type (pipeline.payloads[].words): how a
// program names them. An assignment to a payload writes `word<i>`; a program
// reads `payload.word<i>` (the incoming payload, in raygen the last trace's)
// and `child.word<i>` (the last nested trace's payload).
#pragma once

#include "base/enum_names.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "program/program.h"

namespace rayspec {

// At most this many words in one payload type (mirrored by case.h's
// kMaxPayloadWords; the names word0 .. word57: a 256-byte payload).
constexpr uint32_t kPayloadWordNames = 58;

// "word<i>" (i written in decimal, no leading zero) -> i for
// i < kPayloadWordNames; nullopt for any other name.
std::optional<uint32_t> payloadWordField(const std::string& field);

// A built-in name "payload.word<i>" or "child.word<i>": its prefix
// ("payload" / "child") and i; nullopt for any other name.
struct PayloadWordRead {
  bool child = false;
  uint32_t index = 0;
};
std::optional<PayloadWordRead> payloadWordBuiltin(const std::string& name);

// The extra uint words of a callable data type
// (pipeline.callable_data[].words): a call and call_data write `word<i>`; a
// callable reads `call.word<i>` (its incoming data), a caller
// `callee.word<i>` (its last call's data). The same names, word0 .. word51
// (case.h kMaxCallDataWords).
struct CallWordRead {
  bool callee = false;
  uint32_t index = 0;
};
// "call.word<i>" or "callee.word<i>": which and i; nullopt for any other name.
std::optional<CallWordRead> callWordBuiltin(const std::string& name);

// The extra uint words of the hit attribute (pipeline.hit_attribute.words):
// a report writes `word<i>`, any-hit and closest-hit read `attribute.word<i>`.
// The vec2 and 6 words fill the 32 bytes every device allows
// (maxRayHitAttributeSize).
constexpr uint32_t kMaxAttributeWords = 6;
// "attribute.word<i>" -> i for i < kMaxAttributeWords; nullopt otherwise.
std::optional<uint32_t> attributeWordBuiltin(const std::string& name);

// The sized members of a payload, callable data or hit attribute type
// (pipeline.payloads[].sized, pipeline.callable_data[].sized,
// pipeline.hit_attribute.sized): each a sized scalar or vector of
// program/sized_types.h, at most once, named by its spelling (payload.int8,
// child.u16vec3, call.f16vec4, callee.int64, attribute.f64vec2; a payload,
// call, call_data or report writes `int8: expr`), kept in ValueType order.
using SizedMembers = std::vector<ValueType>;
// "int8", "u16vec3", ... -> its type, for a sized scalar or vector (int32 and
// ivec2..4 included); nullopt for any other name.
std::optional<ValueType> sizedMemberField(const std::string& field);
// The data a sized member read names, by its prefix.
enum class SizedData : uint8_t { Payload, Child, Call, Callee, Attribute };
struct SizedMemberRead {
  SizedData data = SizedData::Payload;
  ValueType type = ValueType::Int8;
};
// "payload.int8", "child.int8", "call.int8", "callee.int8",
// "attribute.int8": which and the type; nullopt for any other name.
std::optional<SizedMemberRead> sizedMemberBuiltin(const std::string& name);
// The GLSL struct member holding a sized type's member: "rs_int8".
std::string sizedMemberGlsl(ValueType t);
// Bytes of a hit attribute block of a vec2, `words` uint words and these
// members, as Vulkan counts it for maxRayHitAttributeSize (the block has no
// explicit offsets: every member aligned to the largest scalar alignment of
// any member, each as large as its components).
uint32_t hitAttributeBytes(uint32_t words, const SizedMembers& members);
// The members of `a` and `b`, in ValueType order (a result type that holds
// any location's).
SizedMembers sizedMembersUnion(const SizedMembers& a, const SizedMembers& b);
// Whether `members` holds `t`.
bool holdsSized(const SizedMembers& members, ValueType t);

// Words indexed by a value (cases/README.md, "Words indexed by a value"):
// the ops {payload_word: i}, {child_word: i}, {call_word: i} and
// {callee_word: i} read (program/ops.h wordArrayOf), and `store: {array: payload.words |
// call.words, index: i, value: v}` writes, word i % N of one data array, N the words of that
// array's type as the stage declares it (Pipeline::indexedWords).
#define RAYSPEC_WORD_ARRAYS(X)                                                        \
  /* the incoming payload (miss, closest-hit, any-hit); in raygen the last trace's */ \
  X(Payload, "payload.words")                                                         \
  X(Child, "child.words")   /* the last nested trace's payload (closest-hit, miss) */ \
  X(Call, "call.words")     /* the incoming callable data (callable) */               \
  X(Callee, "callee.words") /* the last call's data */
enum class WordArray : uint8_t { RAYSPEC_WORD_ARRAYS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(WordArray, RAYSPEC_WORD_ARRAYS);
// The array's name: "payload.words", "child.words", "call.words",
// "callee.words" (a store's `array:`, and the GLSL member it is).
const char* wordArrayName(WordArray which);
// A store's array "payload.words" / "call.words"; nullopt otherwise.
std::optional<WordArray> wordArrayOfStore(const std::string& array);

}  // namespace rayspec
