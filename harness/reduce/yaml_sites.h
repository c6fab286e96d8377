// The places of a case's YAML document that a reduction may shrink: lists
// whose elements may go (rays, instances, geometries, primitives, statements,
// shaders, output fields, flags) and maps whose keys may go (a stage left to
// its default, a ray's or instance's optional field, a build option). The reduction works on the
// document, not on the parsed case, so every variant is a case file that the
// normal parser judges (cases/README.md).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <vector>

namespace rayspec {

struct PathStep {
  bool is_index = false;
  size_t index = 0;
  std::string key;
};
using YamlPath = std::vector<PathStep>;

// The path one step further: to a map's key, or a list's element.
YamlPath plus(YamlPath p, const std::string& key);
YamlPath plus(YamlPath p, size_t index);

// "scene.blas.tri[0].triangles.vertices"
std::string pathText(const YamlPath& path);

// The node at `path` under root (an invalid or null node where there is none).
YAML::Node nodeAt(const YAML::Node& root, const YamlPath& path);

struct Site {
  enum class Kind { Sequence, MapKeys };
  Kind kind = Kind::Sequence;
  YamlPath path;
  std::string part;               // what its units are, for the steps: "rays", "instances", ...
  size_t group = 1;               // Sequence: elements a unit (3: a triangle's vertices, indices)
  size_t units = 0;               // how many units it has now
  std::vector<std::string> keys;  // MapKeys: the keys that may go, in the map's order
};

// Every site of the document, in the order a reduction takes them: the
// launch's rays first (every later variant runs faster), then instances,
// geometries, primitives, then the pipeline and the outputs.
std::vector<Site> reductionSites(const YAML::Node& root);

// The path of every map key whose value is an empty list (`indices: []`,
// `flags: []`, ...), in document order: left by a reduction, each may go
// where the case format does not need it.
std::vector<YamlPath> emptyListKeys(const YAML::Node& root);

// A deep copy of root keeping only the units `kept` (ascending) of the site.
YAML::Node keepUnits(const YAML::Node& root, const Site& site, const std::vector<size_t>& kept);

// Replaces the node at path (which must exist) in a deep copy of root.
YAML::Node replacedAt(const YAML::Node& root, const YamlPath& path, const YAML::Node& value);

// The document as text (the styles it was written in: flow lists stay flow).
std::string emitYaml(const YAML::Node& root);

}  // namespace rayspec
