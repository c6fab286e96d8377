// rays.aim read into an AimSpec (case/aim_rays.h): the parser's reading,
// and what each ray of a parsed case's `aim` form is aimed at (for
// `rayspec show`).
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "case/aim_rays.h"

namespace rayspec {

class YamlReader;

// n: the rays.aim map; false (errors in r) where it is not a valid one.
bool readAimSpec(YamlReader& r, const YAML::Node& n, AimSpec& spec);

// What each ray of `c` is aimed at, by ray, where its text (the case's
// file, or a sweep variant's substituted text) gives its rays by `aim`;
// empty otherwise. With scene.split, the instance, geometry and triangles
// of the mesh as aimed, before the split.
std::vector<AimTarget> aimTargetsOf(const Case& c, const std::string& text);

}  // namespace rayspec
