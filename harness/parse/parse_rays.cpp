// rays: defaults, then exactly one of camera / grid / list / aim / same.
#include <cmath>
#include <sstream>

#include "case/aim_rays.h"
#include "case/camera_rays.h"
#include "case/flag_names.h"
#include "parse/parse_aim.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

// Reads the per-ray fields shared by the defaults and list entries.
void parseRayFields(YamlReader& r, const YAML::Node& n, const std::string& field, Ray& ray) {
  auto get = [&](const char* key) {
    return YamlReader::get(n, key);
  };
  auto f = [&](const char* key) {
    return field.empty() ? std::string(key) : field + "." + key;
  };
  // Non-finite and out-of-range values are allowed: they are R-UB robustness probes.
  if (auto v = get("tmin"); v.IsDefined())
    if (auto x = r.number(v, f("tmin"), true)) ray.tmin = static_cast<float>(*x);
  if (auto v = get("tmax"); v.IsDefined())
    if (auto x = r.number(v, f("tmax"), true)) ray.tmax = static_cast<float>(*x);
  if (auto v = get("flags"); v.IsDefined())
    if (auto x = r.flags(v, f("flags"), rayFlagNames())) ray.flags = *x;
  // Full 32-bit values: the rules on the low bits (R-MASK, R-SBT-*) are tested with them.
  if (auto v = get("cull_mask"); v.IsDefined())
    if (auto x = r.uint(v, f("cull_mask"))) ray.cull_mask = *x;
  if (auto v = get("sbt_offset"); v.IsDefined())
    if (auto x = r.uint(v, f("sbt_offset"))) ray.sbt_offset = *x;
  if (auto v = get("sbt_stride"); v.IsDefined())
    if (auto x = r.uint(v, f("sbt_stride"))) ray.sbt_stride = *x;
  if (auto v = get("miss"); v.IsDefined())
    if (auto x = r.uint(v, f("miss"))) ray.miss = *x;
}

std::string number(float v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// R-UB: ray parameters whose behaviour is undefined (non-finite origin or
// direction, NaN or negative tmin or tmax, tmin > tmax), noted at the field
// written in n; values n does not write come from the defaults, checked there.
void noteUndefinedRay(YamlReader& r, const YAML::Node& n, const std::string& field, const Ray& ray,
                      bool with_origin) {
  auto note = [&](const char* key, const std::string& what) {
    const std::string f = field + "." + key;
    r.undefinedBehaviour(r.loc(YamlReader::get(n, key), f), UndefinedReason::RayParameters,
                         what + ": undefined behaviour (R-UB)");
  };
  if (with_origin) {
    for (const char* key : {"origin", "direction"}) {
      const Vec3& v = std::string(key) == "origin" ? ray.origin : ray.direction;
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        note(key, std::string("the ray ") + key + " is not finite");
    }
  }
  const bool own_tmin = YamlReader::has(n, "tmin"), own_tmax = YamlReader::has(n, "tmax");
  const bool bad_tmin = own_tmin && !(ray.tmin >= 0), bad_tmax = own_tmax && !(ray.tmax >= 0);
  auto negative_or_nan = [](const char* name, float v) {
    return std::string(name) + (std::isnan(v) ? " is NaN" : " " + number(v) + " is negative");
  };
  if (bad_tmin) note("tmin", negative_or_nan("tmin", ray.tmin));
  if (bad_tmax) note("tmax", negative_or_nan("tmax", ray.tmax));
  if (!bad_tmin && !bad_tmax && (own_tmin || own_tmax) && ray.tmin > ray.tmax)
    note(own_tmax ? "tmax" : "tmin",
         "tmax " + number(ray.tmax) + " is below tmin " + number(ray.tmin));
}

std::optional<std::array<uint32_t, 2>> parseSize(YamlReader& r, const YAML::Node& n,
                                                 const std::string& field) {
  if (!n.IsSequence() || n.size() != 2) {
    r.error(n, field, "expected [width, height]");
    return std::nullopt;
  }
  auto w = r.uint(n[0], field + "[0]", 1u << 14), h = r.uint(n[1], field + "[1]", 1u << 14);
  if (!w || !h) return std::nullopt;
  if (*w == 0 || *h == 0) {
    r.error(n, field, "width and height must be at least 1");
    return std::nullopt;
  }
  if (uint64_t(*w) * *h > (1u << 24)) {
    r.error(n, field, "at most 2^24 rays in a launch");
    return std::nullopt;
  }
  return std::array<uint32_t, 2>{*w, *h};
}

void parseCamera(YamlReader& r, const YAML::Node& n, Rays& rays) {
  const std::string field = "rays.camera";
  if (!r.expectMap(n, field, {"size", "origin", "look_at", "up", "fov"})) return;
  bool ok = r.require(n, field, "size") & r.require(n, field, "origin") &
            r.require(n, field, "look_at") & r.require(n, field, "fov");
  if (!ok) return;
  CameraSpec cam;
  auto size = parseSize(r, YamlReader::get(n, "size"), field + ".size");
  auto origin = r.numbers<3>(YamlReader::get(n, "origin"), field + ".origin");
  auto look_at = r.numbers<3>(YamlReader::get(n, "look_at"), field + ".look_at");
  auto fov = r.number(YamlReader::get(n, "fov"), field + ".fov");
  std::optional<std::array<double, 3>> up = cam.up;
  if (YamlReader::has(n, "up")) up = r.numbers<3>(YamlReader::get(n, "up"), field + ".up");
  if (!size || !origin || !look_at || !fov || !up) return;
  if (!(*fov > 0 && *fov < 180)) {
    r.error(YamlReader::get(n, "fov"), field + ".fov", "fov must be in (0, 180) degrees");
    return;
  }
  cam.width = (*size)[0];
  cam.height = (*size)[1];
  cam.origin = *origin;
  cam.look_at = *look_at;
  cam.up = *up;
  cam.fov_degrees = *fov;
  rays.width = cam.width;
  rays.height = cam.height;
  rays.rays = cameraRays(cam, rays.defaults);
  if (rays.rays.empty())
    r.error(n, field, "degenerate camera (look_at equals origin, or up is parallel to the view)");
}

void parseGrid(YamlReader& r, const YAML::Node& n, Rays& rays) {
  const std::string field = "rays.grid";
  if (!r.expectMap(n, field, {"size", "origin", "du", "dv", "direction"})) return;
  bool ok = r.require(n, field, "size") & r.require(n, field, "origin") &
            r.require(n, field, "du") & r.require(n, field, "dv") &
            r.require(n, field, "direction");
  if (!ok) return;
  auto size = parseSize(r, YamlReader::get(n, "size"), field + ".size");
  auto origin = r.numbers<3>(YamlReader::get(n, "origin"), field + ".origin");
  auto du = r.numbers<3>(YamlReader::get(n, "du"), field + ".du");
  auto dv = r.numbers<3>(YamlReader::get(n, "dv"), field + ".dv");
  auto dir = r.numbers<3>(YamlReader::get(n, "direction"), field + ".direction");
  if (!size || !origin || !du || !dv || !dir) return;
  GridSpec g;
  g.width = (*size)[0];
  g.height = (*size)[1];
  g.origin = *origin;
  g.du = *du;
  g.dv = *dv;
  g.direction = *dir;
  rays.width = g.width;
  rays.height = g.height;
  rays.rays = gridRays(g, rays.defaults);
}

// One ray written out (a list entry, rays.same): origin and direction, then
// the per-ray fields over the defaults already in `ray`. False on an error.
bool parseOneRay(YamlReader& r, const YAML::Node& n, const std::string& field, Ray& ray) {
  if (!r.expectMap(n, field,
                   {"origin", "direction", "tmin", "tmax", "flags", "cull_mask", "sbt_offset",
                    "sbt_stride", "miss"}) ||
      !(r.require(n, field, "origin") & r.require(n, field, "direction")))
    return false;
  auto o = r.numbers<3>(YamlReader::get(n, "origin"), field + ".origin", true);
  auto d = r.numbers<3>(YamlReader::get(n, "direction"), field + ".direction", true);
  for (int k = 0; k < 3; ++k) {
    if (o) ray.origin[k] = static_cast<float>((*o)[k]);
    if (d) ray.direction[k] = static_cast<float>((*d)[k]);
  }
  parseRayFields(r, n, field, ray);
  noteUndefinedRay(r, n, field, ray, true);
  return o && d;
}

void parseList(YamlReader& r, const YAML::Node& n, Rays& rays) {
  const std::string field = "rays.list";
  if (!r.expectSeq(n, field)) return;
  if (n.size() == 0) {
    r.error(n, field, "no rays");
    return;
  }
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    const YAML::Node item = n[i];
    Ray ray = rays.defaults;
    parseOneRay(r, item, f, ray);
    rays.rays.push_back(ray);
    rays.list_locs.push_back(r.loc(item, f));
  }
  rays.width = static_cast<uint32_t>(rays.rays.size());
  rays.height = 1;
}

// rays.same: one ray, which every launch id traces; rays.launch gives the
// launch's size.
void parseSame(YamlReader& r, const YAML::Node& n, Rays& rays) {
  Ray ray = rays.defaults;
  if (!parseOneRay(r, n, "rays.same", ray)) return;
  rays.rays = {ray};
  rays.list_locs = {r.loc(n, "rays.same")};
  rays.same = true;
}

void parseAim(YamlReader& r, const YAML::Node& n, const Scene& scene, Rays& rays) {
  const std::string field = "rays.aim";
  AimSpec spec;
  if (!readAimSpec(r, n, spec)) return;
  Result<std::vector<Ray>> aimed = aimRays(scene, spec, rays.defaults);
  if (!aimed) {
    r.error(n, field, aimed.error().message);
    rays.rays.clear();
    return;
  }
  rays.rays = std::move(*aimed);
  if (rays.rays.size() > (1u << 24)) {
    r.error(n, field, "at most 2^24 rays in a launch");
    rays.rays.clear();
    return;
  }
  rays.width = static_cast<uint32_t>(rays.rays.size());
  rays.height = 1;
}

// rays.command: trace_rays (default), indirect or indirect2.
void parseTraceCommand(YamlReader& r, const YAML::Node& v, Rays& rays) {
  const auto name = r.string(v, "rays.command");
  if (!name) return;
  for (TraceCommand c : {TraceCommand::Direct, TraceCommand::Indirect, TraceCommand::Indirect2})
    if (*name == traceCommandName(c)) {
      rays.command = c;
      return;
    }
  r.error(v, "rays.command",
          "unknown trace command '" + *name + "' (trace_rays, indirect, indirect2)");
}

// rays.launch: [width, height, depth], the launch the trace command gets
// (R-LAUNCH-3D). Its size must equal the number of rays the form gave
// (taken in launch order), unless a dimension is 0: such a launch runs
// nothing, and the case keeps no rays. With rays.same any size up to 2^30
// ids goes (above 2^24 only where no program reads the launch id:
// checkWideLaunch): every id traces the one ray.
void parseLaunch(YamlReader& r, const YAML::Node& n, Rays& rays) {
  const std::string field = "rays.launch";
  if (!n.IsSequence() || n.size() != 3) {
    r.error(n, field, "expected [width, height, depth]");
    return;
  }
  std::array<uint32_t, 3> launch{};
  for (size_t k = 0; k < 3; ++k) {
    auto v = r.uint(n[k], field + "[" + std::to_string(k) + "]", 1u << 24);
    if (!v) return;
    launch[k] = *v;
  }
  const uint64_t count = uint64_t(launch[0]) * launch[1] * launch[2];
  if (rays.same && count > kMaxSameLaunchIds) {
    r.error(n, field, "at most 2^30 ids in a rays.same launch");
    return;
  }
  if (!rays.same && count > kMaxTracedLaunchIds) {
    r.error(n, field, "at most 2^24 rays in a launch");
    return;
  }
  if (!rays.same && count != 0 && count != rays.rays.size()) {
    r.error(n, field,
            std::to_string(launch[0]) + " x " + std::to_string(launch[1]) + " x " +
                std::to_string(launch[2]) + " = " + std::to_string(count) +
                " rays, but the rays give " + std::to_string(rays.rays.size()));
    return;
  }
  rays.launch = launch;
  rays.width = launch[0];
  rays.height = launch[1] * launch[2];
  if (count == 0) {
    rays.rays.clear();
    rays.list_locs.clear();
  }
}

}  // namespace

const char* traceCommandName(TraceCommand c) {
  return nameOf(c);
}

void parseRays(YamlReader& r, const YAML::Node& n, const Scene& scene, Rays& rays) {
  if (!r.expectMap(n, "rays",
                   {"camera", "grid", "list", "aim", "same", "tmin", "tmax", "flags", "cull_mask",
                    "sbt_offset", "sbt_stride", "miss", "command", "launch"}))
    return;
  if (auto v = YamlReader::get(n, "command"); v.IsDefined()) parseTraceCommand(r, v, rays);
  parseRayFields(r, n, "rays", rays.defaults);
  rays.defaults_loc = r.loc(n, "rays");
  noteUndefinedRay(r, n, "rays", rays.defaults, false);
  const int forms = YamlReader::has(n, "camera") + YamlReader::has(n, "grid") +
                    YamlReader::has(n, "list") + YamlReader::has(n, "aim") +
                    YamlReader::has(n, "same");
  if (forms != 1) {
    r.error(n, "rays", "exactly one of camera, grid, list, aim or same is required");
    return;
  }
  if (YamlReader::has(n, "same") && !YamlReader::has(n, "launch")) {
    r.error(n, "rays", "rays.same needs rays.launch: the launch size every id of it traces");
    return;
  }
  if (YamlReader::has(n, "camera"))
    parseCamera(r, YamlReader::get(n, "camera"), rays);
  else if (YamlReader::has(n, "grid"))
    parseGrid(r, YamlReader::get(n, "grid"), rays);
  else if (YamlReader::has(n, "aim"))
    parseAim(r, YamlReader::get(n, "aim"), scene, rays);
  else if (YamlReader::has(n, "same"))
    parseSame(r, YamlReader::get(n, "same"), rays);
  else
    parseList(r, YamlReader::get(n, "list"), rays);
  if (auto v = YamlReader::get(n, "launch"); v.IsDefined() && !rays.rays.empty())
    parseLaunch(r, v, rays);
}

}  // namespace rayspec
