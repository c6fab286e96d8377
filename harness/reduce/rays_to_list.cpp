#include "reduce/rays_to_list.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "case/flag_names.h"

namespace rayspec {
namespace {

YAML::Node vectorNode(const Vec3& v, std::string (*text)(float)) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  for (int k = 0; k < 3; ++k) n.push_back(text(v[k]));
  return n;
}

YAML::Node flagsNode(uint32_t flags) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  for (const auto& [name, bit] : rayFlagNames())
    if (flags & bit) n.push_back(std::string(name));
  return n;
}

// One ray, with the fields that differ from the launch's defaults (the
// `rays` map keeps those).
YAML::Node rayNode(const Ray& r, const Ray& d) {
  YAML::Node n(YAML::NodeType::Map);
  n.SetStyle(YAML::EmitterStyle::Flow);
  n["origin"] = vectorNode(r.origin, floatText);
  n["direction"] = vectorNode(r.direction, exactFloatText);
  const auto differs = [](float a, float b) {
    return std::memcmp(&a, &b, sizeof a) != 0;
  };
  if (differs(r.tmin, d.tmin)) n["tmin"] = floatText(r.tmin);
  if (differs(r.tmax, d.tmax)) n["tmax"] = floatText(r.tmax);
  if (r.flags != d.flags) n["flags"] = flagsNode(r.flags);
  if (r.cull_mask != d.cull_mask) n["cull_mask"] = r.cull_mask;
  if (r.sbt_offset != d.sbt_offset) n["sbt_offset"] = r.sbt_offset;
  if (r.sbt_stride != d.sbt_stride) n["sbt_stride"] = r.sbt_stride;
  if (r.miss != d.miss) n["miss"] = r.miss;
  return n;
}

}  // namespace

std::string floatText(float v) {
  return exactFloatText(v == 0.0f ? 0.0f : v);
}

std::string exactFloatText(float v) {
  if (std::isnan(v)) return ".nan";
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

std::optional<YAML::Node> raysAsList(const YAML::Node& rays_map, const Case& c,
                                     const std::vector<uint32_t>& which) {
  if (!rays_map.IsMap() || rays_map["list"] || rays_map["same"] || c.rays.same ||
      c.rays.rays.empty() || which.empty())
    return std::nullopt;
  YAML::Node out(YAML::NodeType::Map);
  for (auto it = rays_map.begin(); it != rays_map.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (key == "camera" || key == "grid" || key == "aim" || key == "launch") continue;
    out[key] = YAML::Clone(it->second);
  }
  YAML::Node list(YAML::NodeType::Sequence);
  for (uint32_t i : which)
    if (i < c.rays.rays.size()) list.push_back(rayNode(c.rays.rays[i], c.rays.defaults));
  if (list.size() == 0) return std::nullopt;
  out["list"] = list;
  return out;
}

}  // namespace rayspec
