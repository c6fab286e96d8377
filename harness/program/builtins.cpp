// The table of built-ins, generated from program/builtin_table.h, and the
// one resolution of a built-in's name.
#include "program/builtins.h"

#include <iterator>

#include "program/payload_words.h"

namespace rayspec {
namespace {

constexpr const char kWordIndex[] = "<i>";      // the index in a word<i> family's name
constexpr const char kSizedIndex[] = "<type>";  // the type in a sized family's name

constexpr Builtin kSizedRows[] = {kBiPayloadSized, kBiChildSized, kBiCallSized, kBiCalleeSized,
                                  kBiAttributeSized};  // in SizedData order

// The row `name` spells exactly, kBiUnknown for none.
Builtin rowNamed(const std::string& name) {
  for (size_t i = 0; i < builtins().size(); ++i)
    if (name == builtins()[i].name) return static_cast<Builtin>(i);
  return kBiUnknown;
}

}  // namespace

std::string stageList(StageMask mask) {
  std::string s;
  for (int i = 0; i < 6; ++i) {
    if (!(mask & (1u << i))) continue;
    if (!s.empty()) s += ", ";
    s += stageName(static_cast<Stage>(i));
  }
  return s;
}

const std::vector<BuiltinInfo>& builtins() {
  using namespace stage_letters;
  using namespace builtin_needs;
  static const std::vector<BuiltinInfo> table = {
#define RAYSPEC_BUILTIN_ROW(id, name, type, stages, needs, glsl, ray_query, meaning) \
  {name, ValueType::type, stages, needs, glsl, ray_query, meaning},
      RAYSPEC_BUILTINS(RAYSPEC_BUILTIN_ROW)
#undef RAYSPEC_BUILTIN_ROW
  };
  return table;
}

BuiltinNeeds builtinNeeds(Builtin b) {
  return b < kBiCount ? builtins()[b].needs : builtin_needs::NoNeeds;
}

std::optional<WordArray> wordArrayOf(Builtin b) {
  switch (b) {
    case kBiPayloadWord:
      return WordArray::Payload;
    case kBiChildWord:
      return WordArray::Child;
    case kBiCallWord:
      return WordArray::Call;
    case kBiCalleeWord:
      return WordArray::Callee;
    default:
      return std::nullopt;
  }
}

std::optional<SizedData> sizedDataOf(Builtin b) {
  for (size_t i = 0; i < std::size(kSizedRows); ++i)
    if (kSizedRows[i] == b) return static_cast<SizedData>(i);
  return std::nullopt;
}

std::optional<BuiltinName> builtinNamed(const std::string& name) {
  // payload.word3 is the table's payload.word<i>, word 3.
  if (auto w = payloadWordBuiltin(name))
    return BuiltinName{w->child ? kBiChildWord : kBiPayloadWord, w->index};
  if (auto i = attributeWordBuiltin(name)) return BuiltinName{kBiAttributeWord, *i};
  if (auto w = callWordBuiltin(name))
    return BuiltinName{w->callee ? kBiCalleeWord : kBiCallWord, w->index};
  if (auto m = sizedMemberBuiltin(name))
    return BuiltinName{kSizedRows[static_cast<size_t>(m->data)], static_cast<uint32_t>(m->type)};
  const Builtin b = rowNamed(name);
  if (b == kBiUnknown || isWordFamily(b) || isSizedFamily(b)) return std::nullopt;
  return BuiltinName{b, 0};
}

std::string builtinSpelling(Builtin id, uint32_t word) {
  if (id >= kBiCount) return "?";
  std::string s = builtins()[id].name;
  if (const size_t at = s.find(kWordIndex); at != std::string::npos)
    s.replace(at, sizeof kWordIndex - 1, std::to_string(word));
  if (const size_t at = s.find(kSizedIndex); at != std::string::npos)
    s.replace(at, sizeof kSizedIndex - 1, valueTypeSpelling(static_cast<ValueType>(word)));
  return s;
}

const BuiltinInfo* findBuiltin(const std::string& name) {
  const std::optional<BuiltinName> b = builtinNamed(name);
  return b ? &builtins()[b->id] : nullptr;
}

ValueType builtinType(Builtin id, uint32_t word) {
  return isSizedFamily(id) ? static_cast<ValueType>(word) : builtins()[id].type;
}

Builtin builtinId(const BuiltinInfo* info) {
  return info ? static_cast<Builtin>(info - builtins().data()) : kBiUnknown;
}

Expr builtinExpr(Builtin id, const SourceLoc& loc, uint32_t word) {
  Expr e;
  e.loc = loc;
  setBuiltin(e, id, word);
  return e;
}

Expr builtinExpr(const std::string& name, const SourceLoc& loc) {
  const std::optional<BuiltinName> b = builtinNamed(name);
  Expr e = builtinExpr(b ? b->id : kBiUnknown, loc, b ? b->word : 0);
  if (!b) e.name = name;
  return e;
}

void setBuiltin(Expr& e, Builtin id, uint32_t word) {
  e.kind = Expr::Kind::Builtin;
  e.op = Op::None;
  e.args.clear();
  e.literal.clear();
  e.builtin = id;
  e.word = isWordFamily(id) || isSizedFamily(id) ? word : 0;
  e.name = builtinSpelling(id, e.word);
  if (id < kBiCount) e.type = builtinType(id, e.word);
}

std::string rayQuerySpelling(const BuiltinInfo& info, bool committed) {
  if (!info.ray_query) return "";
  std::string s = info.ray_query;
  for (size_t at; (at = s.find("$c")) != std::string::npos;)
    s.replace(at, 2, committed ? "true" : "false");
  return s;
}

}  // namespace rayspec
