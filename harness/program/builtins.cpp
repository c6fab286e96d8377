// The table of built-ins, generated from program/builtin_table.h.
#include "program/builtins.h"

#include "program/payload_words.h"

namespace rayspec {

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

const BuiltinInfo* findBuiltin(const std::string& name) {
  // payload.word3 is the table's payload.word<i>.
  if (auto w = payloadWordBuiltin(name))
    return findBuiltin(w->child ? "child.word<i>" : "payload.word<i>");
  if (attributeWordBuiltin(name)) return findBuiltin("attribute.word<i>");
  if (auto w = callWordBuiltin(name))
    return findBuiltin(w->callee ? "callee.word<i>" : "call.word<i>");
  for (const BuiltinInfo& b : builtins())
    if (name == b.name) return &b;
  return nullptr;
}

Builtin builtinId(const BuiltinInfo* info) {
  return info ? static_cast<Builtin>(info - builtins().data()) : kBiUnknown;
}

bool isHitVertexPosition(const std::string& name) {
  const Builtin b = builtinId(findBuiltin(name));
  return b >= kBiVertex0 && b <= kBiVertex2;
}

bool isQueryVertexPosition(const std::string& name) {
  const Builtin b = builtinId(findBuiltin(name));
  return (b >= kBiQCandVertex0 && b <= kBiQCandVertex2) ||
         (b >= kBiQCommittedVertex0 && b <= kBiQCommittedVertex2);
}

std::string rayQuerySpelling(const BuiltinInfo& info, bool committed) {
  if (!info.ray_query) return "";
  std::string s = info.ray_query;
  for (size_t at; (at = s.find("$c")) != std::string::npos;)
    s.replace(at, 2, committed ? "true" : "false");
  return s;
}

}  // namespace rayspec
