// The whole numbers of a case that a reduction may lower: a generator's
// counts (a mesh's or a box grid's cells, a fan's triangles, an instance
// grid's cells), the launch's size (a ray grid's, a camera's, `launch`), the
// fields that index or mask (an instance's custom index, SBT offset, mask and top level;
// a ray's cull mask, SBT offset and stride, miss index), and every whole
// number of the stages' statements (loop trip counts, constants, record and
// slot indices). A sweep's variable is reduced where its value landed: the
// variant's text holds the number. Coordinates and other fractions stay
// bit-exact, as do negative numbers.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "reduce/yaml_sites.h"

namespace rayspec {

struct NumberSite {
  YamlPath path;
  uint64_t value = 0;  // above 0: a site of value 0 is as low as it goes
  std::string part;    // "generator", "launch", "instance field", "ray field", "statement"
};

// A scalar that is a whole number written plainly: decimal, or hexadecimal
// with 0x (no sign, no leading zero, nothing after it).
std::optional<uint64_t> wholeNumber(const YAML::Node& n);

// Every number site of the document, in document order of the parts above.
std::vector<NumberSite> numberSites(const YAML::Node& root);

}  // namespace rayspec
