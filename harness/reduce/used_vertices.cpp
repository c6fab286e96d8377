#include "reduce/used_vertices.h"

#include <map>
#include <set>

#include "reduce/yaml_sites.h"

namespace rayspec {
namespace {

YAML::Node flowList() {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

// The map without `keys`, in its order and style.
YAML::Node without(const YAML::Node& map, const std::set<std::string>& keys) {
  YAML::Node out(YAML::NodeType::Map);
  out.SetStyle(map.Style());
  for (auto it = map.begin(); it != map.end(); ++it)
    if (!keys.count(it->first.Scalar())) out[it->first.Scalar()] = YAML::Clone(it->second);
  return out;
}

}  // namespace

std::optional<YAML::Node> usedVerticesOnly(const YAML::Node& triangles) {
  if (!triangles.IsMap()) return std::nullopt;
  const YAML::Node indices = nodeAt(triangles, {{false, 0, "indices"}}),
                   vertices = nodeAt(triangles, {{false, 0, "vertices"}});
  if (!indices.IsSequence() || !vertices.IsSequence()) return std::nullopt;
  if (indices.size() == 0) {  // the vertices make the triangles, three by three
    YAML::Node out = without(triangles, {"indices"});
    YAML::Node listed(YAML::NodeType::Sequence);
    listed.SetStyle(vertices.Style());
    for (size_t i = 0; i < vertices.size() / 3 * 3; ++i) listed.push_back(vertices[i]);
    out["vertices"] = listed;
    return out;
  }
  std::set<size_t> used;
  for (size_t i = 0; i < indices.size(); ++i) used.insert(indices[i].as<size_t>(0));
  if (used.size() >= vertices.size() || *used.rbegin() >= vertices.size()) return std::nullopt;
  std::map<size_t, size_t> renumbered;
  YAML::Node new_vertices(YAML::NodeType::Sequence), new_indices = flowList();
  new_vertices.SetStyle(vertices.Style());
  for (size_t v : used) {
    renumbered[v] = renumbered.size();
    new_vertices.push_back(vertices[v]);
  }
  for (size_t i = 0; i < indices.size(); ++i)
    new_indices.push_back(renumbered[indices[i].as<size_t>(0)]);
  YAML::Node map = YAML::Clone(triangles);
  map["vertices"] = new_vertices;
  map["indices"] = new_indices;
  return map;
}

}  // namespace rayspec
