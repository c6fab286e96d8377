// Payload types by location (pipeline.payloads) and the miss shaders, each
// of which may name the location whose payload type it takes:
//   payloads: [{words: 0}, {words: 4}]      # location 0, location 1
//   miss: [[...], {payload: 1, program: [...]}]
// A hit group names its location with `payload:` (parse_pipeline.cpp).
#include "parse/parse_parts.h"

namespace rayspec {

void parseWordTypes(YamlReader& r, const YAML::Node& n, const WordTypes& types,
                    std::vector<uint32_t>& out) {
  const std::string f = types.field;
  if (!r.expectSeq(n, f)) return;
  if (n.size() == 0 || n.size() > types.max_locations) {
    r.error(n, f,
            "needs 1 to " + std::to_string(types.max_locations) + " " + types.what +
                " types (one per location), got " + std::to_string(n.size()));
    return;
  }
  out.assign(n.size(), 0);
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string fi = f + "[" + std::to_string(i) + "]";
    if (n[i].IsNull()) continue;  // `- {}`: the fixed members only
    if (!r.expectMap(n[i], fi, {"words"})) continue;
    if (auto v = YamlReader::get(n[i], "words"); v.IsDefined())
      if (auto w = r.uint(v, fi + ".words", types.max_words)) out[i] = *w;
  }
}

void parsePayloadTypes(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  parseWordTypes(r, n, {"pipeline.payloads", "payload", kMaxPayloadLocations, kMaxPayloadWords},
                 p.payload_words);
}

std::optional<uint32_t> parseWordLocation(YamlReader& r, const YAML::Node& n,
                                          const std::string& field, const WordTypes& types,
                                          size_t declared) {
  auto k = r.uint(n, field);
  if (k && *k >= declared) {
    r.error(n, field,
            std::string(types.what) + " location " + std::to_string(*k) + ", but " + types.field +
                " declares " + std::to_string(declared));
    return std::nullopt;
  }
  return k;
}

std::optional<uint32_t> parsePayloadLocation(YamlReader& r, const YAML::Node& n,
                                             const std::string& field, const Pipeline& p) {
  return parseWordLocation(r, n, field, {"pipeline.payloads", "payload", 0, 0},
                           p.payload_words.size());
}

void parseMissShaders(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (!r.expectSeq(n, "pipeline.miss")) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "pipeline.miss[" + std::to_string(i) + "]";
    Program prog;
    uint32_t location = 0;
    if (n[i].IsMap() && YamlReader::has(n[i], "program")) {
      if (r.expectMap(n[i], f, {"program", "payload"})) {
        parseProgram(r, YamlReader::get(n[i], "program"), f + ".program", prog);
        if (auto v = YamlReader::get(n[i], "payload"); v.IsDefined())
          location = parsePayloadLocation(r, v, f + ".payload", p).value_or(0);
      }
    } else {
      parseProgram(r, n[i], f, prog);
    }
    p.miss.push_back(std::move(prog));
    p.miss_payload.push_back(location);
  }
}

}  // namespace rayspec
