#include "reduce/number_sites.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>

namespace rayspec {
namespace {

void addNumber(std::vector<NumberSite>& sites, const YAML::Node& root, const YamlPath& path,
               const std::string& part) {
  if (const std::optional<uint64_t> v = wholeNumber(nodeAt(root, path)); v && *v > 0)
    sites.push_back({path, *v, part});
}

// Each whole number of the list of numbers at path ([x, y] cells or sizes).
void addNumbers(std::vector<NumberSite>& sites, const YAML::Node& root, const YamlPath& path,
                const std::string& part) {
  const YAML::Node n = nodeAt(root, path);
  for (size_t i = 0; n.IsSequence() && i < n.size(); ++i)
    addNumber(sites, root, plus(path, i), part);
}

void addFields(std::vector<NumberSite>& sites, const YAML::Node& root, const YamlPath& path,
               std::initializer_list<const char*> keys, const std::string& part) {
  for (const char* key : keys) addNumber(sites, root, plus(path, key), part);
}

// Every whole number under path, at any depth.
void addEvery(std::vector<NumberSite>& sites, const YAML::Node& root, const YamlPath& path,
              const std::string& part) {
  const YAML::Node n = nodeAt(root, path);
  if (n.IsScalar()) {
    addNumber(sites, root, path, part);
  } else if (n.IsSequence()) {
    for (size_t i = 0; i < n.size(); ++i) addEvery(sites, root, plus(path, i), part);
  } else if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it)
      if (it->first.IsScalar()) addEvery(sites, root, plus(path, it->first.Scalar()), part);
  }
}

void generatorSites(std::vector<NumberSite>& sites, const YAML::Node& root) {
  const YamlPath blas{{false, 0, "scene"}, {false, 0, "blas"}};
  const YAML::Node blases = nodeAt(root, blas);
  for (auto it = blases.begin(); blases.IsMap() && it != blases.end(); ++it) {
    const YAML::Node geometries = it->second;
    for (size_t g = 0; geometries.IsSequence() && g < geometries.size(); ++g) {
      const YamlPath at = plus(plus(blas, it->first.Scalar()), g);
      for (const char* form : {"grid", "triangulation"})
        addNumbers(sites, root, plus(plus(plus(at, "triangles"), form), "cells"), "generator");
      addNumber(sites, root, plus(plus(plus(at, "triangles"), "fan"), "triangles"), "generator");
      addNumbers(sites, root, plus(plus(plus(at, "aabbs"), "grid"), "cells"), "generator");
    }
  }
  const YamlPath instances{{false, 0, "scene"}, {false, 0, "instances"}};
  const YAML::Node inst = nodeAt(root, instances);
  for (size_t i = 0; inst.IsSequence() && i < inst.size(); ++i) {
    addNumbers(sites, root, plus(plus(plus(instances, i), "grid"), "cells"), "generator");
    addFields(sites, root, plus(instances, i), {"custom_index", "sbt_offset", "mask", "tlas"},
              "instance field");
  }
}

void raySites(std::vector<NumberSite>& sites, const YAML::Node& root) {
  const YamlPath rays{{false, 0, "rays"}};
  addNumbers(sites, root, plus(plus(rays, "camera"), "size"), "launch");
  addNumbers(sites, root, plus(plus(rays, "grid"), "size"), "launch");
  addNumbers(sites, root, plus(rays, "launch"), "launch");
  addNumber(sites, root, plus(plus(rays, "aim"), "edge_points"), "launch");
  const std::initializer_list<const char*> fields{"cull_mask", "sbt_offset", "sbt_stride", "miss"};
  addFields(sites, root, rays, fields, "ray field");
  const YAML::Node list = nodeAt(root, plus(rays, "list"));
  for (size_t i = 0; list.IsSequence() && i < list.size(); ++i)
    addFields(sites, root, plus(plus(rays, "list"), i), fields, "ray field");
}

}  // namespace

std::optional<uint64_t> wholeNumber(const YAML::Node& n) {
  if (!n.IsDefined() || !n.IsScalar()) return std::nullopt;
  const std::string& s = n.Scalar();
  const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) ||
      (s.size() > 1 && s[0] == '0' && !hex))
    return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s.c_str(), &end, hex ? 16 : 10);
  if (errno != 0 || end != s.c_str() + s.size()) return std::nullopt;
  return static_cast<uint64_t>(v);
}

std::vector<NumberSite> numberSites(const YAML::Node& root) {
  std::vector<NumberSite> sites;
  generatorSites(sites, root);
  raySites(sites, root);
  addEvery(sites, root, {{false, 0, "pipeline"}}, "statement");
  return sites;
}

}  // namespace rayspec
