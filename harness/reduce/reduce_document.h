// The reduction of a case's document: the launch turned into a list of its
// failing rays; the sizes lowered (a generator's cells, the launch: every
// later variant builds and traces less) and the launch listed again;
// generated meshes written out; then pass after pass until one changes
// nothing: delta debugging over every site (reduce/yaml_sites.h) in turn,
// unused vertices dropped, operators replaced by an operand
// (reduce/operand_sites.h), every whole number lowered (reduce/number_sites.h).
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
