// A launch written as a camera, a grid or an aim, turned into an explicit
// `rays: {list: [...]}` of some of its rays, exactly as the launch uploads
// them (float32 printed with 9 significant digits, which reads back to the
// same float; the sign of a zero kept in directions only): a reduction can
// then drop rays one by one.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case/case.h"

namespace rayspec {

// A number as case text: 9 significant digits, .nan, .inf, -.inf; a zero
// as 0, whatever its sign (a vertex or an origin at -0 is where it is at 0).
std::string floatText(float v);
// The same, a negative zero kept as -0: where its sign matters (a ray
// direction's component: 1 / -0 is -inf) and the case had it.
std::string exactFloatText(float v);

// The document's `rays` map with its form (camera, grid, aim) replaced by a
// list of the rays `which` (launch indices) and its launch size dropped.
// nullopt: the rays are a list already, `same`, or empty.
std::optional<YAML::Node> raysAsList(const YAML::Node& rays_map, const Case& c,
                                     const std::vector<uint32_t>& which);

}  // namespace rayspec
