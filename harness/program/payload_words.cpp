#include "program/payload_words.h"

#include <algorithm>

#include "program/locals.h"

namespace rayspec {

std::optional<uint32_t> payloadWordField(const std::string& field) {
  const std::string prefix = "word";
  if (field.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  const std::string digits = field.substr(prefix.size());
  if (digits.empty() || digits.size() > 2 || (digits.size() > 1 && digits[0] == '0'))
    return std::nullopt;
  uint32_t i = 0;
  for (char d : digits) {
    if (d < '0' || d > '9') return std::nullopt;
    i = i * 10 + static_cast<uint32_t>(d - '0');
  }
  if (i >= kPayloadWordNames) return std::nullopt;
  return i;
}

std::optional<PayloadWordRead> payloadWordBuiltin(const std::string& name) {
  for (bool child : {false, true}) {
    const std::string prefix = child ? "child." : "payload.";
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    if (auto i = payloadWordField(name.substr(prefix.size()))) return PayloadWordRead{child, *i};
  }
  return std::nullopt;
}

std::optional<CallWordRead> callWordBuiltin(const std::string& name) {
  for (bool callee : {false, true}) {
    const std::string prefix = callee ? "callee." : "call.";
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    if (auto i = payloadWordField(name.substr(prefix.size()))) return CallWordRead{callee, *i};
  }
  return std::nullopt;
}

std::optional<uint32_t> attributeWordBuiltin(const std::string& name) {
  const std::string prefix = "attribute.";
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  const auto i = payloadWordField(name.substr(prefix.size()));
  if (!i || *i >= kMaxAttributeWords) return std::nullopt;
  return i;
}

std::optional<ValueType> sizedMemberField(const std::string& field) {
  const std::optional<ValueType> t = valueTypeNamed(field);
  if (!t || !isSized(*t)) return std::nullopt;
  return t;
}

std::optional<SizedMemberRead> sizedMemberBuiltin(const std::string& name) {
  static const std::pair<const char*, SizedData> kPrefixes[] = {
      {"payload.", SizedData::Payload},
      {"child.", SizedData::Child},
      {"call.", SizedData::Call},
      {"callee.", SizedData::Callee},
      {"attribute.", SizedData::Attribute}};
  for (const auto& [prefix, data] : kPrefixes) {
    const std::string p = prefix;
    if (name.compare(0, p.size(), p) != 0) continue;
    if (auto t = sizedMemberField(name.substr(p.size()))) return SizedMemberRead{data, *t};
  }
  return std::nullopt;
}

std::string sizedMemberGlsl(ValueType t) {
  return std::string("rs_") + valueTypeSpelling(t);
}

uint32_t hitAttributeBytes(uint32_t words, const SizedMembers& members) {
  uint32_t align = 4;  // the vec2's and the words' scalars
  for (ValueType t : members)
    align = std::max(align, static_cast<uint32_t>(sizedType(t)->bits) / 8);
  auto place = [&](uint32_t at, uint32_t size) {
    return (at + align - 1) / align * align + size;
  };
  uint32_t end = 8;  // the vec2
  if (words) end = place(end, 4 * words);
  for (ValueType t : members)
    end = place(end, static_cast<uint32_t>(sizedType(t)->bits / 8 * componentCount(t)));
  return end;
}

SizedMembers sizedMembersUnion(const SizedMembers& a, const SizedMembers& b) {
  SizedMembers out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

bool holdsSized(const SizedMembers& members, ValueType t) {
  return std::find(members.begin(), members.end(), t) != members.end();
}

const char* wordArrayName(WordArray which) {
  return nameOf(which);
}

std::optional<WordArray> wordArrayOfStore(const std::string& array) {
  for (WordArray w : {WordArray::Payload, WordArray::Call})
    if (array == wordArrayName(w)) return w;
  return std::nullopt;
}

}  // namespace rayspec
