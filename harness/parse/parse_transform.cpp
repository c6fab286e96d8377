// Reads a transform: identity, 12 numbers (row-major 3x4), or its parts.
#include <cmath>

#include "case/transform.h"
#include "parse/parse_parts.h"

namespace rayspec {

std::optional<Transform> parseTransform(YamlReader& r, const YAML::Node& n,
                                        const std::string& field) {
  if (n.IsScalar() && n.Scalar() == "identity") return kIdentity;
  if (n.IsSequence()) {
    auto v = r.numbers<12>(n, field);
    if (!v) return std::nullopt;
    Transform t;
    for (int i = 0; i < 12; ++i) t[i] = static_cast<float>((*v)[i]);
    return t;
  }
  if (!n.IsMap()) {
    r.error(n, field, "expected identity, 12 numbers, or {translate, scale, rotate}");
    return std::nullopt;
  }
  if (!r.expectMap(n, field, {"translate", "scale", "rotate"})) return std::nullopt;
  TransformParts parts;
  bool ok = true;
  if (auto t = YamlReader::get(n, "translate"); t.IsDefined()) {
    if (auto v = r.numbers<3>(t, field + ".translate"))
      parts.translate = *v;
    else
      ok = false;
  }
  if (auto s = YamlReader::get(n, "scale"); s.IsDefined()) {
    if (s.IsSequence()) {
      if (auto v = r.numbers<3>(s, field + ".scale"))
        parts.scale = *v;
      else
        ok = false;
    } else if (auto v = r.number(s, field + ".scale")) {
      parts.scale = {*v, *v, *v};
    } else {
      ok = false;
    }
  }
  if (auto rot = YamlReader::get(n, "rotate"); rot.IsDefined()) {
    const std::string f = field + ".rotate";
    if (r.expectMap(rot, f, {"axis", "degrees"}) && r.require(rot, f, "axis") &&
        r.require(rot, f, "degrees")) {
      auto axis = r.numbers<3>(YamlReader::get(rot, "axis"), f + ".axis");
      auto deg = r.number(YamlReader::get(rot, "degrees"), f + ".degrees");
      if (axis && deg) {
        if ((*axis)[0] == 0 && (*axis)[1] == 0 && (*axis)[2] == 0) {
          r.error(YamlReader::get(rot, "axis"), f + ".axis", "rotation axis is zero");
          ok = false;
        } else {
          parts.axis = *axis;
          parts.degrees = *deg;
        }
      } else {
        ok = false;
      }
    } else {
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return composeTransform(parts);
}

}  // namespace rayspec
