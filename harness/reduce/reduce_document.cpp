#include "reduce/reduce_document.h"

#include <algorithm>
#include <set>

#include "reduce/delta_debug.h"
#include "reduce/number_sites.h"
#include "reduce/operand_sites.h"
#include "reduce/rays_to_list.h"
#include "reduce/used_vertices.h"
#include "reduce/yaml_sites.h"

namespace rayspec {
namespace {

constexpr size_t kMaxListedRays = 4096;  // rays a list holds at most: the first failing ones
constexpr int kMaxPasses = 6;

// The document with `value` at path, kept when it still fails.
bool tryReplace(YAML::Node& doc, const YamlPath& path, const YAML::Node& value,
                const std::string& what, VariantJudge& judge) {
  YAML::Node candidate = replacedAt(doc, path, value);
  if (!judge.fails(emitYaml(candidate), what)) return false;
  doc = candidate;
  return true;
}

// A camera, grid or aim becomes a list: of the failing rays, else of all.
void listTheRays(YAML::Node& doc, const Case& c, const std::vector<uint32_t>& failing,
                 VariantJudge& judge) {
  const YamlPath rays{{false, 0, "rays"}};
  const YAML::Node now = nodeAt(doc, rays);
  if (!now.IsMap() || now["list"]) return;
  const std::vector<uint32_t> first(failing.begin(),
                                    failing.begin() + std::min(failing.size(), kMaxListedRays));
  if (const std::optional<YAML::Node> some = raysAsList(now, c, first))
    if (tryReplace(doc, rays, *some, "rays: the failing rays as a list", judge)) return;
  if (c.rays.rays.size() > kMaxListedRays) return;
  std::vector<uint32_t> all;
  for (uint32_t i = 0; i < c.rays.rays.size(); ++i) all.push_back(i);
  if (const std::optional<YAML::Node> every = raysAsList(nodeAt(doc, rays), c, all))
    tryReplace(doc, rays, *every, "rays: every ray as a list", judge);
}

YAML::Node flowSeq() {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

// A generated mesh (grid, fan, triangulation) written out as its vertices
// and indices, so that its triangles can go one by one.
void writeOutMeshes(YAML::Node& doc, VariantJudge& judge) {
  const ParseResult parsed = judge.parse(emitYaml(doc));
  if (!parsed.value) return;
  const Case& c = *parsed.value;
  const YamlPath blas{{false, 0, "scene"}, {false, 0, "blas"}};
  for (const Blas& b : c.scene.blases) {
    for (size_t g = 0; g < b.geometries.size(); ++g) {
      const YamlPath tri = {
          blas[0], blas[1], {false, 0, b.name}, {true, g, ""}, {false, 0, "triangles"}};
      const YAML::Node old = nodeAt(doc, tri);
      if (!old.IsMap() || old["vertex_format"] ||
          !(old["grid"] || old["fan"] || old["triangulation"]))
        continue;
      const Geometry& geo = b.geometries[g];
      YAML::Node out(YAML::NodeType::Map);
      YAML::Node vertices = flowSeq();
      for (const Vec3& v : geo.vertices) {
        YAML::Node p = flowSeq();
        for (int k = 0; k < 3; ++k) p.push_back(floatText(v[k]));
        vertices.push_back(p);
      }
      out["vertices"] = vertices;
      if (!geo.indices.empty()) {
        YAML::Node indices = flowSeq();
        for (uint32_t i : geo.indices) indices.push_back(i);
        out["indices"] = indices;
      }
      tryReplace(doc, tri, out, pathText(tri) + ": the generated mesh written out", judge);
    }
  }
}

// Indexed triangles keep only the vertices their indices name, renumbered;
// `indices: []` goes (reduce/used_vertices.h).
void dropUnusedVertices(YAML::Node& doc, VariantJudge& judge) {
  const YamlPath blas{{false, 0, "scene"}, {false, 0, "blas"}};
  const YAML::Node blases = nodeAt(doc, blas);
  if (!blases.IsMap()) return;
  std::vector<std::string> names;
  for (auto it = blases.begin(); it != blases.end(); ++it) names.push_back(it->first.Scalar());
  for (const std::string& name : names) {
    const YAML::Node geometries = nodeAt(doc, plus(blas, name));
    for (size_t g = 0; geometries.IsSequence() && g < geometries.size(); ++g) {
      const YamlPath tri = plus(plus(plus(blas, name), g), "triangles");
      if (const std::optional<YAML::Node> used = usedVerticesOnly(nodeAt(doc, tri)))
        tryReplace(doc, tri, *used, pathText(tri) + ": unused vertices dropped", judge);
    }
  }
}

// Each key whose list was emptied (`flags: []`, a ray query's `aabb: []`,
// ...) left out where the case still fails so; those the case format needs
// (an empty box geometry's `aabbs: []`) stay. `settled`: the paths tried.
void dropEmptyLists(YAML::Node& doc, VariantJudge& judge, std::set<std::string>& settled) {
  for (const YamlPath& path : emptyListKeys(doc)) {
    if (judge.stopped() || !settled.insert(pathText(path)).second) continue;
    const YamlPath parent(path.begin(), path.end() - 1);
    const YAML::Node map = nodeAt(doc, parent);
    YAML::Node out(YAML::NodeType::Map);
    out.SetStyle(map.Style());
    for (auto it = map.begin(); it != map.end(); ++it)
      if (it->first.Scalar() != path.back().key) out[it->first.Scalar()] = it->second;
    tryReplace(doc, parent, out, pathText(path) + ": the empty list left out", judge);
  }
}

// The smallest value of the number at `site` that still fails: 0, else the
// least a binary search of [1, value) finds (the least failing one where
// failing grows with the number, a smaller failing one anyway).
uint64_t lowestFailing(const YAML::Node& doc, const NumberSite& site, VariantJudge& judge) {
  const std::string what =
      pathText(site.path) + " (" + site.part + "): " + std::to_string(site.value) + " -> ";
  const auto fails = [&](uint64_t v) {
    return judge.fails(emitYaml(replacedAt(doc, site.path, YAML::Node(v))),
                       what + std::to_string(v));
  };
  if (fails(0)) return 0;
  uint64_t low = 1, high = site.value;  // high fails
  while (low < high && !judge.stopped()) {
    const uint64_t mid = low + (high - low) / 2;
    if (fails(mid))
      high = mid;
    else
      low = mid + 1;
  }
  return high;
}

// Each number site of the parts asked for (none: every part) lowered as far
// as the case still fails. `settled` holds "path=value" of every number
// already as low as it went, so that a later pass does not search again.
bool lowerNumbers(YAML::Node& doc, VariantJudge& judge, std::set<std::string>& settled,
                  const std::set<std::string>& parts = {}) {
  bool progress = false;
  while (!judge.stopped()) {
    std::optional<NumberSite> next;
    for (const NumberSite& s : numberSites(doc))
      if ((parts.empty() || parts.count(s.part)) &&
          !settled.count(pathText(s.path) + "=" + std::to_string(s.value))) {
        next = s;
        break;
      }
    if (!next) break;
    const uint64_t low = lowestFailing(doc, *next, judge);
    if (low < next->value) {
      doc = replacedAt(doc, next->path, YAML::Node(low));
      progress = true;
    }
    settled.insert(pathText(next->path) + "=" + std::to_string(low));
  }
  return progress;
}

// Each operator replaced by the first of its operands with which the case
// still fails. `settled` holds "path=operator" of those tried already.
bool hoistOperands(YAML::Node& doc, VariantJudge& judge, std::set<std::string>& settled) {
  bool progress = false;
  while (!judge.stopped()) {
    std::optional<OperandSite> next;
    std::string key;
    for (const OperandSite& s : operandSites(doc)) {
      key = pathText(s.path) + "=" + emitYaml(nodeAt(doc, s.path));
      if (!settled.count(key)) {
        next = s;
        break;
      }
    }
    if (!next) break;
    settled.insert(key);
    for (size_t i = 0; i < next->operands; ++i)
      if (tryReplace(doc, next->path, operandOf(doc, *next, i),
                     pathText(next->path) + " (operator): its operand " + std::to_string(i),
                     judge)) {
        progress = true;
        break;
      }
  }
  return progress;
}

// After the launch shrank: its failing rays, now few enough, as a list.
void listTheRaysAgain(YAML::Node& doc, VariantJudge& judge) {
  const std::string text = emitYaml(doc);
  const CaseOutcome* now = judge.keptOutcome(text);
  const ParseResult parsed = judge.parse(text);
  if (!now || !parsed.value) return;
  listTheRays(doc, *parsed.value, failingRays(*now, judge.signature()), judge);
}

std::string attemptText(const Site& site, const std::vector<size_t>& kept) {
  std::string what = pathText(site.path) + " (" + site.part + "): keep " +
                     std::to_string(kept.size()) + " of " + std::to_string(site.units);
  if (site.kind == Site::Kind::MapKeys) {
    what += " keys [";
    for (size_t i = 0; i < kept.size(); ++i) what += (i ? ", " : "") + site.keys[kept[i]];
    what += "]";
  }
  return what;
}

// One pass over the sites, listed again after each (a site that shrank
// moves the paths of those after it). Whether anything went.
bool onePass(YAML::Node& doc, VariantJudge& judge) {
  bool progress = false;
  for (size_t next = 0; !judge.stopped(); ++next) {
    const std::vector<Site> sites = reductionSites(doc);
    if (next >= sites.size()) break;
    const Site& site = sites[next];
    const DeltaResult r = deltaDebug(site.units, [&](const std::vector<size_t>& kept) {
      return judge.fails(emitYaml(keepUnits(doc, site, kept)), attemptText(site, kept));
    });
    if (r.kept.size() < site.units) {
      doc = keepUnits(doc, site, r.kept);
      progress = true;
    }
  }
  return progress;
}

}  // namespace

YAML::Node reduceDocument(const YAML::Node& start, const Case& original,
                          const std::vector<uint32_t>& failing, VariantJudge& judge) {
  YAML::Node doc = YAML::Clone(start);
  listTheRays(doc, original, failing, judge);
  std::set<std::string> settled, hoisted, emptied;
  // The sizes first: every later variant builds and launches less.
  if (lowerNumbers(doc, judge, settled, {"generator", "launch"})) listTheRaysAgain(doc, judge);
  writeOutMeshes(doc, judge);
  for (int pass = 0; pass < kMaxPasses && !judge.stopped(); ++pass) {
    bool progress = onePass(doc, judge);
    dropUnusedVertices(doc, judge);
    progress = hoistOperands(doc, judge, hoisted) || progress;
    if (lowerNumbers(doc, judge, settled)) {
      listTheRaysAgain(doc, judge);
      progress = true;
    }
    if (!progress) break;
  }
  dropEmptyLists(doc, judge, emptied);
  return doc;
}

}  // namespace rayspec
