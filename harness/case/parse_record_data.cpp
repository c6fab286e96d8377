// Shader record data: {uints: [..]} | {floats: [..]}, at most 8 words.
#include <bit>

#include "case/case_parts.h"

namespace rayspec {

std::optional<std::vector<uint32_t>> parseRecordData(YamlReader& r, const YAML::Node& n,
                                                     const std::string& field) {
  if (!r.expectMap(n, field, {"uints", "floats"})) return std::nullopt;
  const bool u = YamlReader::has(n, "uints"), f = YamlReader::has(n, "floats");
  if (u == f) {
    r.error(n, field, "expected exactly one of uints or floats");
    return std::nullopt;
  }
  const char* key = u ? "uints" : "floats";
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
    if (u) {
      auto v = r.uint(list[i], fi);
      if (v)
        words.push_back(*v);
      else
        ok = false;
    } else {
      auto v = r.number(list[i], fi, true);
      if (!v) {
        ok = false;
        continue;
      }
      const float x = static_cast<float>(*v);
      words.push_back(std::bit_cast<uint32_t>(x));
    }
  }
  if (!ok) return std::nullopt;
  return words;
}

}  // namespace rayspec
