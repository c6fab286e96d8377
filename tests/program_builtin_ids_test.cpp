// Built-ins resolved once, by id (program/builtins.h): every spelling the
// table has names its row, builtinExpr / setBuiltin keep an expression's id,
// word, name and type in step, and the needs column names the interface a
// read needs (what the GLSL, the plan and the checks read from it).
#include <gtest/gtest.h>

#include <string>

#include "program/builtins.h"
#include "program/ops.h"

namespace rayspec {
namespace {

// The last word a family's name may index (payload_words.h).
uint32_t lastWord(Builtin b) {
  return b == kBiAttributeWord ? kMaxAttributeWords - 1 : kPayloadWordNames - 1;
}

std::string nameOfRow(Builtin b) {
  return builtins()[b].name;
}

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

// The indices a row's names take: a word<i> family's words, a <type>
// family's sized types (as ValueType), 0 elsewhere.
std::vector<uint32_t> indicesOf(Builtin b) {
  if (isWordFamily(b)) return {0, 3, lastWord(b)};
  if (isSizedFamily(b))
    return {static_cast<uint32_t>(ValueType::Int8), static_cast<uint32_t>(ValueType::Int32),
            static_cast<uint32_t>(ValueType::Float64Vec4)};
  return {0};
}

TEST(BuiltinIds, EverySpellingOfTheTableResolvesToItsRow) {
  for (int i = 0; i < kBiCount; ++i) {
    const Builtin b = static_cast<Builtin>(i);
    EXPECT_EQ(isWordFamily(b), nameOfRow(b).find("<i>") != std::string::npos) << nameOfRow(b);
    EXPECT_EQ(isSizedFamily(b), nameOfRow(b).find("<type>") != std::string::npos) << nameOfRow(b);
    for (uint32_t word : indicesOf(b)) {
      const std::string spelled = builtinSpelling(b, word);
      const std::optional<BuiltinName> named = builtinNamed(spelled);
      ASSERT_TRUE(named.has_value()) << spelled;
      EXPECT_EQ(named->id, b) << spelled;
      EXPECT_EQ(named->word, word) << spelled;
      EXPECT_EQ(findBuiltin(spelled), &builtins()[b]) << spelled;
      const Expr e = builtinExpr(spelled);
      EXPECT_EQ(e.kind, Expr::Kind::Builtin);
      EXPECT_EQ(e.builtin, b) << spelled;
      EXPECT_EQ(e.word, word) << spelled;
      EXPECT_EQ(e.name, spelled);
      EXPECT_EQ(e.type, isSizedFamily(b) ? static_cast<ValueType>(word) : builtins()[b].type)
          << spelled;
    }
  }
  EXPECT_EQ(builtinSpelling(kBiPayloadWord, 3), "payload.word3");
  EXPECT_EQ(builtinSpelling(kBiAttributeWord, 5), "attribute.word5");
  EXPECT_EQ(builtinSpelling(kBiHitT, 3), "hit_t");  // no family: the index is no part of it
  EXPECT_EQ(builtinSpelling(kBiCalleeSized, static_cast<uint32_t>(ValueType::Uint16Vec3)),
            "callee.u16vec3");
}

// A family's own row name, an index beyond the family or written with a
// leading zero, and a near miss name no row.
TEST(BuiltinIds, NamesNoRowReadsAreUnknown) {
  for (const char* name :
       {"payload.word<i>", "attribute.word<i>", "payload.word58", "attribute.word6",
        "callee.word58", "payload.word03", "payload.word", "payload.<type>", "payload.uint",
        "payload.vec3", "child.i8vec5", "primitive", "hit_tt", "committed.", ""}) {
    EXPECT_FALSE(builtinNamed(name).has_value()) << name;
    EXPECT_EQ(findBuiltin(name), nullptr) << name;
    const Expr e = builtinExpr(std::string(name));
    EXPECT_EQ(e.builtin, kBiUnknown) << name;
    EXPECT_EQ(e.name, name);  // kept for the type checker's message
  }
}

TEST(BuiltinIds, SetBuiltinKeepsNameIdWordAndTypeInStep) {
  SourceLoc at;
  at.line = 4;
  Expr e = builtinExpr(kBiPrimitive, at);
  EXPECT_EQ(e.name, "primitive_id");
  EXPECT_EQ(e.type, ValueType::Uint);
  EXPECT_EQ(e.loc.line, 4);
  setBuiltin(e, kBiPayloadWord, 7);
  EXPECT_EQ(e.builtin, kBiPayloadWord);
  EXPECT_EQ(e.word, 7u);
  EXPECT_EQ(e.name, "payload.word7");
  setBuiltin(e, kBiHitT, 7);  // a row of no family drops the word
  EXPECT_EQ(e.word, 0u);
  EXPECT_EQ(e.name, "hit_t");
  EXPECT_EQ(e.type, ValueType::Float);
  EXPECT_EQ(e.loc.line, 4);
  // An operator made a read: its arguments and op go.
  Expr sum = opExpr(Op::Add, {builtinExpr(kBiLaunchX, at), builtinExpr(kBiLaunchY, at)},
                    ValueType::Uint, at);
  setBuiltin(sum, kBiCullMask);
  EXPECT_EQ(sum.kind, Expr::Kind::Builtin);
  EXPECT_TRUE(sum.args.empty());
  EXPECT_EQ(sum.op, Op::None);
  EXPECT_TRUE(isBuiltin(sum, kBiCullMask));
  EXPECT_FALSE(isBuiltin(sum, kBiLaunchX));
  // Every row: what setBuiltin writes reads back as that row.
  for (int i = 0; i < kBiCount; ++i) {
    const Builtin b = static_cast<Builtin>(i);
    setBuiltin(e, b, indicesOf(b).back());
    const std::optional<BuiltinName> back = builtinNamed(e.name);
    ASSERT_TRUE(back.has_value()) << e.name;
    EXPECT_EQ(back->id, e.builtin) << e.name;
    EXPECT_EQ(back->word, e.word) << e.name;
    EXPECT_EQ(e.type, builtinType(b, e.word)) << e.name;
  }
}

// The interface a read needs comes from the row's needs column: the same
// rows the GLSL, the stage interface and the faults listed by name before.
TEST(BuiltinIds, NeedsColumnNamesTheDataARowReads) {
  using namespace builtin_needs;
  for (int i = 0; i < kBiCount; ++i) {
    const Builtin b = static_cast<Builtin>(i);
    const std::string n = nameOfRow(b);
    const BuiltinNeeds needs = builtinNeeds(b);
    EXPECT_EQ((needs & InPayload) != 0, startsWith(n, "payload.")) << n;
    EXPECT_EQ((needs & ChildPayload) != 0, startsWith(n, "child.")) << n;
    EXPECT_EQ((needs & CallData) != 0, startsWith(n, "call.")) << n;
    EXPECT_EQ((needs & CalleeData) != 0, startsWith(n, "callee.")) << n;
    EXPECT_EQ((needs & HitAttribute) != 0,
              n == "barycentrics" || n == "attribute.word<i>" || n == "attribute.<type>")
        << n;
    EXPECT_EQ(isHitVertexPosition(b), startsWith(n, "vertex_position")) << n;
    EXPECT_EQ(isQueryVertexPosition(b), n.find(".vertex_position") != std::string::npos) << n;
    EXPECT_EQ(isCandidateGetter(b), startsWith(n, "candidate.")) << n;
    EXPECT_EQ(isCommittedGetter(b), startsWith(n, "committed.")) << n;
    EXPECT_EQ(isInstanceTransform(b),
              startsWith(n, "object_to_world") || startsWith(n, "world_to_object"))
        << n;
    EXPECT_EQ(wordArrayOf(b).has_value(), isWordFamily(b) && b != kBiAttributeWord) << n;
  }
  EXPECT_EQ(builtinNeeds(kBiUnknown), NoNeeds);
}

// The type checker reads the id: a read the parser could not resolve is an
// unknown built-in under the name it was written as.
TEST(BuiltinIds, TypeCheckerRefusesAnUnresolvedRead) {
  Expr unknown = builtinExpr(std::string("hit_tt"));
  const Result<void> r = typeCheck(unknown, Stage::ClosestHit);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("unknown built-in 'hit_tt'"), std::string::npos);
  Expr known = builtinExpr(kBiHitT, {});
  EXPECT_TRUE(typeCheck(known, Stage::ClosestHit).ok());
  EXPECT_EQ(known.type, ValueType::Float);
}

}  // namespace
}  // namespace rayspec
