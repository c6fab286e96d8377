#include "reduce/yaml_sites.h"

#include <cctype>
#include <set>

namespace rayspec {
namespace {

YAML::Node undefinedNode() {
  return YAML::Node(YAML::NodeType::Undefined);
}

YAML::Node childOf(const YAML::Node& n, const PathStep& s) {
  if (s.is_index) {
    if (!n.IsSequence() || s.index >= n.size()) return undefinedNode();
    return n[s.index];
  }
  if (!n.IsMap()) return undefinedNode();
  for (auto it = n.begin(); it != n.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == s.key) return it->second;
  return undefinedNode();
}

bool present(const YAML::Node& n) {
  return n.IsDefined() && !n.IsNull();
}

bool isNumber(const YAML::Node& n) {
  if (!n.IsScalar() || n.Scalar().empty()) return false;
  const unsigned char c = static_cast<unsigned char>(n.Scalar()[0]);
  return std::isdigit(c) || c == '-' || c == '+' || c == '.';
}

// A list of numbers is a vector, a matrix or data words: its length is part
// of its meaning, never something to shrink.
bool allNumbers(const YAML::Node& seq) {
  for (size_t i = 0; i < seq.size(); ++i)
    if (!isNumber(seq[i])) return false;
  return true;
}

void addSeq(std::vector<Site>& sites, const YAML::Node& root, const YamlPath& path,
            const std::string& part, size_t group = 1) {
  const YAML::Node n = nodeAt(root, path);
  if (!n.IsSequence() || n.size() == 0) return;
  if (group > 1 && n.size() % group != 0) group = 1;
  sites.push_back({Site::Kind::Sequence, path, part, group, n.size() / group, {}});
}

// The keys of the map at path that may go, all but those in `keep`.
void addKeys(std::vector<Site>& sites, const YAML::Node& root, const YamlPath& path,
             const std::string& part, const std::set<std::string>& keep = {}) {
  const YAML::Node n = nodeAt(root, path);
  if (!n.IsMap()) return;
  Site s{Site::Kind::MapKeys, path, part, 1, 0, {}};
  for (auto it = n.begin(); it != n.end(); ++it)
    if (it->first.IsScalar() && !keep.count(it->first.Scalar()))
      s.keys.push_back(it->first.Scalar());
  s.units = s.keys.size();
  if (s.units) sites.push_back(std::move(s));
}

// Geometries, then each geometry's primitives (triangles by their indices
// where they have some, else by their vertices; boxes one each).
void sceneSites(std::vector<Site>& sites, const YAML::Node& root) {
  const YamlPath blas{{false, 0, "scene"}, {false, 0, "blas"}};
  const YAML::Node blases = nodeAt(root, blas);
  if (!blases.IsMap()) return;
  std::vector<std::string> names;
  for (auto it = blases.begin(); it != blases.end(); ++it) names.push_back(it->first.Scalar());
  for (const std::string& name : names) addSeq(sites, root, plus(blas, name), "geometries");
  for (const std::string& name : names) {
    const YAML::Node geometries = nodeAt(root, plus(blas, name));
    if (!geometries.IsSequence()) continue;
    for (size_t g = 0; g < geometries.size(); ++g) {
      const YamlPath at = plus(plus(blas, name), g);
      const YAML::Node tri = nodeAt(root, plus(at, "triangles"));
      if (present(nodeAt(root, plus(plus(at, "triangles"), "indices"))))
        addSeq(sites, root, plus(plus(at, "triangles"), "indices"), "primitives", 3);
      else if (tri.IsMap())
        addSeq(sites, root, plus(plus(at, "triangles"), "vertices"), "primitives", 3);
      addSeq(sites, root, plus(at, "aabbs"), "primitives");
    }
  }
}

// Every list under `path` that is not a list of numbers: statements,
// shaders, groups, records, fields.
void listSites(std::vector<Site>& sites, const YAML::Node& root, const YamlPath& path,
               const std::string& part) {
  const YAML::Node n = nodeAt(root, path);
  if (n.IsSequence()) {
    if (n.size() && !allNumbers(n)) addSeq(sites, root, path, part);
    for (size_t i = 0; i < n.size(); ++i) listSites(sites, root, plus(path, i), part);
  } else if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it)
      if (it->first.IsScalar()) listSites(sites, root, plus(path, it->first.Scalar()), part);
  }
}

// The flags lists of rays, instances, geometries and builds: each flag may go.
void flagSites(std::vector<Site>& sites, const YAML::Node& root) {
  const YamlPath rays{{false, 0, "rays"}};
  addSeq(sites, root, plus(rays, "flags"), "flags");
  const YAML::Node list = nodeAt(root, plus(rays, "list"));
  for (size_t i = 0; list.IsSequence() && i < list.size(); ++i)
    addSeq(sites, root, plus(plus(plus(rays, "list"), i), "flags"), "flags");
  const YamlPath scene{{false, 0, "scene"}};
  const YAML::Node inst = nodeAt(root, plus(scene, "instances"));
  for (size_t i = 0; inst.IsSequence() && i < inst.size(); ++i)
    addSeq(sites, root, plus(plus(plus(scene, "instances"), i), "flags"), "flags");
  const YAML::Node blases = nodeAt(root, plus(scene, "blas"));
  for (auto it = blases.begin(); blases.IsMap() && it != blases.end(); ++it)
    for (size_t g = 0; it->second.IsSequence() && g < it->second.size(); ++g)
      addSeq(sites, root, plus(plus(plus(plus(scene, "blas"), it->first.Scalar()), g), "flags"),
             "flags");
  addSeq(sites, root, plus(plus(scene, "build"), "flags"), "flags");
}

void collectEmptyLists(const YAML::Node& n, const YamlPath& path, std::vector<YamlPath>& out) {
  if (n.IsSequence()) {
    for (size_t i = 0; i < n.size(); ++i) collectEmptyLists(n[i], plus(path, i), out);
  } else if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it) {
      if (!it->first.IsScalar()) continue;
      const YamlPath at = plus(path, it->first.Scalar());
      if (it->second.IsSequence() && it->second.size() == 0)
        out.push_back(at);
      else
        collectEmptyLists(it->second, at, out);
    }
  }
}

void keySites(std::vector<Site>& sites, const YAML::Node& root) {
  const YamlPath rays{{false, 0, "rays"}};
  addKeys(sites, root, rays, "ray defaults", {"camera", "grid", "list", "aim", "same"});
  const YAML::Node list = nodeAt(root, plus(rays, "list"));
  for (size_t i = 0; list.IsSequence() && i < list.size(); ++i)
    addKeys(sites, root, plus(plus(rays, "list"), i), "ray fields", {"origin", "direction"});
  const YamlPath instances{{false, 0, "scene"}, {false, 0, "instances"}};
  const YAML::Node inst = nodeAt(root, instances);
  for (size_t i = 0; inst.IsSequence() && i < inst.size(); ++i)
    addKeys(sites, root, plus(instances, i), "instance fields", {"blas"});
  addKeys(sites, root, {{false, 0, "scene"}}, "scene parts", {"blas", "instances"});
  addKeys(sites, root, {{false, 0, "scene"}, {false, 0, "build"}}, "build options");
  addKeys(sites, root, {{false, 0, "scene"}, {false, 0, "blas"}}, "bottom levels");
  flagSites(sites, root);
}

}  // namespace

YamlPath plus(YamlPath p, const std::string& key) {
  p.push_back({false, 0, key});
  return p;
}

YamlPath plus(YamlPath p, size_t index) {
  p.push_back({true, index, ""});
  return p;
}

std::string pathText(const YamlPath& path) {
  std::string out;
  for (const PathStep& s : path)
    out += s.is_index ? "[" + std::to_string(s.index) + "]" : (out.empty() ? "" : ".") + s.key;
  return out.empty() ? "(top)" : out;
}

YAML::Node nodeAt(const YAML::Node& root, const YamlPath& path) {
  YAML::Node cur;
  cur.reset(root);
  for (const PathStep& s : path) {
    YAML::Node next = childOf(cur, s);
    if (!next.IsDefined()) return next;
    cur.reset(next);
  }
  return cur;
}

std::vector<Site> reductionSites(const YAML::Node& root) {
  std::vector<Site> sites;
  addSeq(sites, root, {{false, 0, "rays"}, {false, 0, "list"}}, "rays");
  addSeq(sites, root, {{false, 0, "scene"}, {false, 0, "instances"}}, "instances");
  sceneSites(sites, root);
  keySites(sites, root);
  const YamlPath pipeline{{false, 0, "pipeline"}};
  for (const char* part : {"hit_groups", "miss", "callables", "libraries"})
    addSeq(sites, root, plus(pipeline, part), part);
  const YAML::Node groups = nodeAt(root, plus(pipeline, "hit_groups"));
  for (size_t i = 0; groups.IsSequence() && i < groups.size(); ++i)
    addKeys(sites, root, plus(plus(pipeline, "hit_groups"), i), "hit group stages");
  addKeys(sites, root, pipeline, "pipeline parts");
  listSites(sites, root, pipeline, "statements");
  listSites(sites, root, {{false, 0, "outputs"}}, "outputs");
  return sites;
}

std::vector<YamlPath> emptyListKeys(const YAML::Node& root) {
  std::vector<YamlPath> out;
  collectEmptyLists(root, {}, out);
  return out;
}

YAML::Node replacedAt(const YAML::Node& root, const YamlPath& path, const YAML::Node& value) {
  if (path.empty()) return YAML::Clone(value);
  YAML::Node copy = YAML::Clone(root);
  YAML::Node parent = nodeAt(copy, YamlPath(path.begin(), path.end() - 1));
  const PathStep& last = path.back();
  if (last.is_index)
    parent[last.index] = YAML::Clone(value);
  else
    parent[last.key] = YAML::Clone(value);
  return copy;
}

YAML::Node keepUnits(const YAML::Node& root, const Site& site, const std::vector<size_t>& kept) {
  const YAML::Node old = nodeAt(root, site.path);
  if (site.kind == Site::Kind::Sequence) {
    YAML::Node seq(YAML::NodeType::Sequence);
    seq.SetStyle(old.Style());
    for (size_t u : kept)
      for (size_t k = 0; k < site.group; ++k) seq.push_back(old[u * site.group + k]);
    return replacedAt(root, site.path, seq);
  }
  std::set<std::string> going(site.keys.begin(), site.keys.end());
  for (size_t u : kept) going.erase(site.keys[u]);
  YAML::Node map(YAML::NodeType::Map);
  map.SetStyle(old.Style());
  for (auto it = old.begin(); it != old.end(); ++it)
    if (!going.count(it->first.Scalar())) map[it->first.Scalar()] = it->second;
  return replacedAt(root, site.path, map);
}

std::string emitYaml(const YAML::Node& root) {
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

}  // namespace rayspec
