#include "program/payload_words.h"

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

const char* wordArrayName(WordArray which) {
  return nameOf(which);
}

std::optional<WordArray> wordArrayOfStore(const std::string& array) {
  for (WordArray w : {WordArray::Payload, WordArray::Call})
    if (array == wordArrayName(w)) return w;
  return std::nullopt;
}

}  // namespace rayspec
