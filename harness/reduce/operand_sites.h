// The operators of a case's stage programs ({add: [a, b]}, {x: v}, any op of
// program/ops.h) that a reduction may replace by one of their operands: a
// failure that needs only `a` keeps `a`. A replacement that no longer types
// (a Bool where a Uint was) does not parse and costs no run.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <vector>

#include "reduce/yaml_sites.h"

namespace rayspec {

struct OperandSite {
  YamlPath path;        // the operator's map
  size_t operands = 0;  // how many it has
};

// Every operator under `pipeline`, outer ones first.
std::vector<OperandSite> operandSites(const YAML::Node& root);

// Operand i of the operator at site.
YAML::Node operandOf(const YAML::Node& root, const OperandSite& site, size_t i);

}  // namespace rayspec
