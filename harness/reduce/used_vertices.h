// Indexed triangles with only the vertices their indices name, for a
// reduction that dropped triangles (reduce/reduce_document.h).
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>

namespace rayspec {

// `triangles` (a geometry's triangles map: vertices and indices) with only
// the vertices its indices name, renumbered in their order. `indices: []`
// (a reduction's "keep none" of them) is no index buffer: the vertices
// make the triangles three by three (Geometry::primitiveCount), so the key
// goes and so do the vertices past the last whole triangle; the same
// triangles. nullopt: every vertex is used already, or the map is not
// indexed triangles whose indices all name a vertex.
std::optional<YAML::Node> usedVerticesOnly(const YAML::Node& triangles);

}  // namespace rayspec
