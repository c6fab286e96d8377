// Shader record data: {uints: [..]} | {floats: [..]} | {words: [..]} (each
// a uint or a float as it is written), at most 8 words.
#include <bit>

#include "parse/parse_parts.h"

namespace rayspec {

namespace {

// One word of {words: [..]}: a number written as a Uint (no '.', 'e' or
// sign) is that uint, any other a float's bits.
std::optional<uint32_t> mixedWord(YamlReader& r, const YAML::Node& n, const std::string& field) {
  uint64_t u = 0;
  if (isPlainScalar(n) && parseUintText(n.Scalar(), u) && u <= 0xFFFFFFFFull)
    return static_cast<uint32_t>(u);
  const auto v = r.number(n, field, true);
  if (!v) return std::nullopt;
  return std::bit_cast<uint32_t>(static_cast<float>(*v));
}

}  // namespace

std::optional<std::vector<uint32_t>> parseRecordData(YamlReader& r, const YAML::Node& n,
                                                     const std::string& field) {
  if (!r.expectMap(n, field, {"uints", "floats", "words"})) return std::nullopt;
  const char* keys[] = {"uints", "floats", "words"};
  const char* key = nullptr;
  int given = 0;
  for (const char* k : keys)
    if (YamlReader::has(n, k)) {
      key = k;
      ++given;
    }
  if (given != 1) {
    r.error(n, field, "expected exactly one of uints, floats or words");
    return std::nullopt;
  }
  const std::string sub = field + "." + key;
  const YAML::Node list = YamlReader::get(n, key);
  if (!r.expectSeq(list, sub)) return std::nullopt;
  if (list.size() > 8) {
    r.error(list, sub, "at most 8 words of shader record data");
    return std::nullopt;
  }
  std::vector<uint32_t> words;
  bool ok = true;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string fi = sub + "[" + std::to_string(i) + "]";
    std::optional<uint32_t> w;
    if (key[0] == 'u') {
      w = r.uint(list[i], fi);
    } else if (key[0] == 'w') {
      w = mixedWord(r, list[i], fi);
    } else if (auto v = r.number(list[i], fi, true)) {
      w = std::bit_cast<uint32_t>(static_cast<float>(*v));
    }
    if (w)
      words.push_back(*w);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return words;
}

}  // namespace rayspec
