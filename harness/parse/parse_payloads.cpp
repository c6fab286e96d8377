// Payload types by location (pipeline.payloads) and the miss shaders, each
// of which may name the location whose payload type it takes:
//   payloads: [{words: 0}, {words: 4, sized: [int8, f16vec4]}]  # location 0, 1
//   miss: [[...], {payload: 1, program: [...]}]
// A hit group names its location with `payload:` (parse_pipeline.cpp).
#include "parse/parse_parts.h"

namespace rayspec {

std::optional<SizedMembers> parseSizedMembers(YamlReader& r, const YAML::Node& n,
                                              const std::string& field) {
  if (!r.expectSeq(n, field)) return std::nullopt;
  SizedMembers members;
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string fi = field + "[" + std::to_string(i) + "]";
    const auto name = r.string(n[i], fi);
    const auto t = name ? sizedMemberField(*name) : std::nullopt;
    if (name && !t)
      r.error(n[i], fi, "unknown sized type '" + *name + "' (int8 .. float64, i8vec2 .. f64vec4)");
    else if (t && holdsSized(members, *t))
      r.error(n[i], fi, "sized type '" + *name + "' listed twice (one member per type)");
    else if (t)
      members = sizedMembersUnion(members, {*t});
    ok = ok && t && members.size() == i + 1;
  }
  if (!ok) return std::nullopt;
  return members;
}

void parseWordTypes(YamlReader& r, const YAML::Node& n, const WordTypes& types,
                    std::vector<uint32_t>& out, std::vector<SizedMembers>& sized) {
  const std::string f = types.field;
  if (!r.expectSeq(n, f)) return;
  if (n.size() == 0 || n.size() > types.max_locations) {
    r.error(n, f,
            "needs 1 to " + std::to_string(types.max_locations) + " " + types.what +
                " types (one per location), got " + std::to_string(n.size()));
    return;
  }
  out.assign(n.size(), 0);
  sized.assign(n.size(), {});
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string fi = f + "[" + std::to_string(i) + "]";
    if (n[i].IsNull()) continue;  // `- {}`: the fixed members only
    if (!r.expectMap(n[i], fi, {"words", "sized"})) continue;
    if (auto v = YamlReader::get(n[i], "words"); v.IsDefined())
      if (auto w = r.uint(v, fi + ".words", types.max_words)) out[i] = *w;
    if (auto v = YamlReader::get(n[i], "sized"); v.IsDefined())
      sized[i] = parseSizedMembers(r, v, fi + ".sized").value_or(SizedMembers{});
  }
}

void parsePayloadTypes(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  parseWordTypes(r, n, {"pipeline.payloads", "payload", kMaxPayloadLocations, kMaxPayloadWords},
                 p.payload_words, p.payload_sized);
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
