// The reduction of a case's document: the launch turned into a list of its
// failing rays, generated meshes written out, then delta debugging over every
// site (reduce/yaml_sites.h) in turn, pass after pass until a pass removes
// nothing; indexed triangles lose the vertices no index names.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <vector>

#include "case/case.h"
#include "reduce/variant_judge.h"

namespace rayspec {

// The smallest document found that still fails the same way (`doc` itself
// when nothing could go). original: doc parsed; failing: its failing rays.
YAML::Node reduceDocument(const YAML::Node& doc, const Case& original,
                          const std::vector<uint32_t>& failing, VariantJudge& judge);

}  // namespace rayspec
