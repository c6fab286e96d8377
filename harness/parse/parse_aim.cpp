#include "parse/parse_aim.h"

#include "parse/parse_parts.h"

namespace rayspec {
namespace {

bool featureList(YamlReader& r, const YAML::Node& at, const std::string& f, AimSpec& spec) {
  if (!r.expectSeq(at, f)) return false;
  spec.vertices = spec.edges = spec.faces = false;
  for (size_t i = 0; i < at.size(); ++i) {
    const auto name = r.string(at[i], f + "[" + std::to_string(i) + "]");
    if (!name) return false;
    if (*name == "vertices")
      spec.vertices = true;
    else if (*name == "edges")
      spec.edges = true;
    else if (*name == "faces")
      spec.faces = true;
    else {
      r.error(at[i], f + "[" + std::to_string(i) + "]",
              "unknown feature '" + *name + "' (vertices, edges, faces)");
      return false;
    }
  }
  return true;
}

}  // namespace

bool readAimSpec(YamlReader& r, const YAML::Node& n, AimSpec& spec) {
  const std::string field = "rays.aim";
  if (!r.expectMap(
          n, field,
          {"instance", "geometry", "at", "edge_points", "offset", "direction_scale", "every"}) ||
      !r.require(n, field, "offset"))
    return false;
  auto get = [&](const char* key) {
    return YamlReader::get(n, key);
  };
  bool ok = true;
  auto uint_field = [&](const char* key, uint32_t max, uint32_t& out) {
    if (!YamlReader::has(n, key)) return;
    if (auto v = r.uint(get(key), field + "." + key, max))
      out = *v;
    else
      ok = false;
  };
  uint_field("instance", kInstanceFieldMask, spec.instance);
  uint_field("geometry", kInstanceFieldMask, spec.geometry);
  uint_field("edge_points", 64, spec.edge_points);
  uint_field("every", 1u << 20, spec.every);
  if (spec.every == 0) {
    r.error(get("every"), field + ".every", "must be at least 1");
    ok = false;
  }
  if (YamlReader::has(n, "at") && !featureList(r, get("at"), field + ".at", spec)) ok = false;
  if (auto o = r.numbers<3>(get("offset"), field + ".offset"))
    spec.offset = *o;
  else
    ok = false;
  if (YamlReader::has(n, "direction_scale")) {
    auto s = r.number(get("direction_scale"), field + ".direction_scale");
    if (s && *s > 0)
      spec.direction_scale = *s;
    else if (s)
      r.error(get("direction_scale"), field + ".direction_scale", "must be positive");
    ok = ok && s && *s > 0;
  }
  return ok;
}

std::vector<AimTarget> aimTargetsOf(const Case& c, const std::string& text) {
  std::vector<Error> errors;
  YamlReader r(c.file, errors);
  AimSpec spec;
  std::vector<AimTarget> targets;
  // rays.aim aims at the scene as parsed before scene.split moves the mesh's
  // triangles apart (parse_case.cpp): where the case splits, that scene again.
  Scene unsplit;
  const Scene* aimed = &c.scene;
  try {
    const YAML::Node root = YAML::Load(text);
    const YAML::Node aim = YamlReader::get(YamlReader::get(root, "rays"), "aim");
    if (!aim.IsDefined() || !readAimSpec(r, aim, spec)) return {};
    const YAML::Node scene = YamlReader::get(root, "scene");
    if (scene.IsMap() && YamlReader::has(scene, "split")) {
      parseScene(r, scene, unsplit);
      aimed = &unsplit;
    }
  } catch (const YAML::Exception&) {
    return {};
  }
  if (!errors.empty() || !aimRays(*aimed, spec, c.rays.defaults, &targets)) return {};
  // rays.launch may run fewer (none): then no ray is aimed.
  if (targets.size() != c.rays.rays.size()) return {};
  return targets;
}

}  // namespace rayspec
