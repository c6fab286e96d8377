#include "report/cts_map.h"

#include <filesystem>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "base/generated_part.h"
#include "base/whole_file.h"
#include "parse/yaml_shape.h"

namespace rayspec {

namespace {

constexpr uint64_t kMaxCtsMapBytes = 1u << 20;

Error mapError(const std::string& path, const YAML::Mark& m, const std::string& field,
               std::string message) {
  return Error{SourceLoc{path, m.line + 1, m.column + 1, field}, std::move(message)};
}

// The keys a map node may have; any other is an error at its place.
Result<void> onlyKeys(const std::string& path, const YAML::Node& node, const std::string& where,
                      const std::set<std::string>& keys) {
  if (!node.IsMap()) return mapError(path, node.Mark(), where, "expected a map");
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "";
    if (!keys.count(key)) {
      std::string known;
      for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
      return mapError(path, it->first.Mark(), where + "." + key,
                      "unknown field (known: " + known + ")");
    }
  }
  return {};
}

Result<std::string> readText(const std::string& path, const YAML::Node& node,
                             const std::string& field, bool required) {
  const YAML::Node v = node[field];
  if (!v) {
    if (required) return mapError(path, node.Mark(), field, "missing");
    return std::string();
  }
  if (!v.IsScalar() || v.Scalar().empty())
    return mapError(path, v.Mark(), field, "expected one non-empty string");
  return v.Scalar();
}

Result<std::vector<std::string>> readTexts(const std::string& path, const YAML::Node& node,
                                           const std::string& field) {
  const YAML::Node v = node[field];
  std::vector<std::string> out;
  if (!v) return out;
  if (!v.IsSequence()) return mapError(path, v.Mark(), field, "expected a list of strings");
  for (const YAML::Node& item : v) {
    if (!item.IsScalar() || item.Scalar().empty())
      return mapError(path, item.Mark(), field, "expected a non-empty string");
    out.push_back(item.Scalar());
  }
  return out;
}

Result<CtsAxis> readAxis(const std::string& path, const YAML::Node& node,
                         const std::string& where) {
  RAYSPEC_TRY_VOID(onlyKeys(path, node, where, {"axis", "cases", "through", "how", "not_covered"}));
  CtsAxis a;
  RAYSPEC_TRY(a.axis, readText(path, node, "axis", true));
  RAYSPEC_TRY(a.cases, readTexts(path, node, "cases"));
  RAYSPEC_TRY(a.through, readTexts(path, node, "through"));
  RAYSPEC_TRY(a.how, readText(path, node, "how", false));
  RAYSPEC_TRY(a.not_covered, readText(path, node, "not_covered", false));
  if (a.covered() == !a.not_covered.empty())
    return mapError(path, node.Mark(), where + "." + a.axis,
                    a.covered() ? "an axis with cases or paths is covered: drop not_covered"
                                : "an axis without cases or paths needs not_covered: why not");
  return a;
}

Result<CtsGroup> readGroup(const std::string& path, const YAML::Node& node) {
  RAYSPEC_TRY_VOID(onlyKeys(path, node, "group", {"group", "source", "axes"}));
  CtsGroup g;
  RAYSPEC_TRY(g.group, readText(path, node, "group", true));
  RAYSPEC_TRY(g.source, readText(path, node, "source", true));
  const YAML::Node axes = node["axes"];
  if (!axes || !axes.IsSequence() || axes.size() == 0)
    return mapError(path, node.Mark(), g.group + ".axes", "expected a list of one axis or more");
  for (const YAML::Node& a : axes) {
    RAYSPEC_TRY(CtsAxis axis, readAxis(path, a, g.group));
    g.axes.push_back(std::move(axis));
  }
  return g;
}

Result<CtsList> readList(const std::string& path, const YAML::Node& node) {
  RAYSPEC_TRY_VOID(onlyKeys(path, node, "list", {"list", "mustpass", "counts", "groups"}));
  CtsList l;
  RAYSPEC_TRY(l.name, readText(path, node, "list", true));
  RAYSPEC_TRY(l.mustpass, readText(path, node, "mustpass", true));
  RAYSPEC_TRY(l.counts_file, readText(path, node, "counts", true));
  const YAML::Node groups = node["groups"];
  if (!groups || !groups.IsSequence())
    return mapError(path, node.Mark(), l.name + ".groups", "expected a list of groups");
  for (const YAML::Node& g : groups) {
    RAYSPEC_TRY(CtsGroup group, readGroup(path, g));
    l.groups.push_back(std::move(group));
  }
  return l;
}

Result<YAML::Node> loadYamlFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return errorMessage(path + ": no such file (expected the map of CTS groups, lists: [...])");
  RAYSPEC_TRY(const std::string text, readWholeFile(path, kMaxCtsMapBytes));
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    return mapError(path, e.mark, "", yamlTooDeepMessage());
  } catch (const YAML::Exception& e) {
    return mapError(path, e.mark, "", "malformed YAML: " + e.msg);
  }
  if (const auto problem = yamlShapeProblem(root))
    return mapError(path, problem->mark, "", problem->message);
  return root;
}

// A table cell: a '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string codeList(const std::vector<std::string>& items, const char* prefix) {
  std::string out;
  for (const std::string& i : items) out += (out.empty() ? "`" : " `") + (prefix + i) + "`";
  return out;
}

// One axis in the row's last cell: what the CTS varies, then the cases and
// paths that cover it (and how), or why nothing does.
std::string axisText(const CtsAxis& a) {
  if (!a.covered()) return "• " + cell(a.axis) + ": **not covered**, " + cell(a.not_covered);
  std::string where = codeList(a.cases, "");
  const std::string paths = codeList(a.through, "--through ");
  if (!paths.empty()) where += (where.empty() ? "" : " ") + paths;
  std::string out = "• " + cell(a.axis) + ": " + where;
  if (!a.how.empty()) out += "; " + cell(a.how);
  return out;
}

std::string groupRow(const CtsGroup& g, long tests) {
  std::string axes;
  for (const CtsAxis& a : g.axes) axes += (axes.empty() ? "" : "<br>") + axisText(a);
  return "| " + g.group + " | " + std::to_string(tests) + " | " +
         ctsCoverageName(groupCoverage(g)) + " | " + axes + " |\n";
}

std::string totalsTable(const CtsList& list, const CtsCounts& counts) {
  long groups[3] = {0, 0, 0}, tests[3] = {0, 0, 0};
  for (const CtsGroup& g : list.groups) {
    const auto c = static_cast<size_t>(groupCoverage(g));
    ++groups[c];
    const auto it = counts.tests.find(g.group);
    tests[c] += it == counts.tests.end() ? 0 : it->second;
  }
  std::ostringstream out;
  out << "| coverage | groups | tests |\n|---|---|---|\n";
  for (CtsCoverage c : {CtsCoverage::Full, CtsCoverage::Partial, CtsCoverage::None})
    out << "| " << ctsCoverageName(c) << " | " << groups[static_cast<size_t>(c)] << " | "
        << tests[static_cast<size_t>(c)] << " |\n";
  return out.str();
}

}  // namespace

CtsCoverage groupCoverage(const CtsGroup& group) {
  size_t covered = 0;
  for (const CtsAxis& a : group.axes) covered += a.covered() ? 1 : 0;
  if (covered == group.axes.size()) return CtsCoverage::Full;
  return covered == 0 ? CtsCoverage::None : CtsCoverage::Partial;
}

const char* ctsCoverageName(CtsCoverage c) {
  switch (c) {
    case CtsCoverage::Full:
      return "full";
    case CtsCoverage::Partial:
      return "partial";
    case CtsCoverage::None:
      return "none";
  }
  return "?";
}

Result<std::vector<CtsList>> loadCtsMap(const std::string& path) {
  RAYSPEC_TRY(const YAML::Node root, loadYamlFile(path));
  RAYSPEC_TRY_VOID(onlyKeys(path, root, "", {"lists"}));
  const YAML::Node lists = root["lists"];
  if (!lists || !lists.IsSequence())
    return mapError(path, root.Mark(), "lists", "expected a list of mustpass lists");
  std::vector<CtsList> out;
  for (const YAML::Node& l : lists) {
    RAYSPEC_TRY(CtsList list, readList(path, l));
    out.push_back(std::move(list));
  }
  return out;
}

std::string ctsCountsPath(const std::string& map_path, const CtsList& list) {
  const std::filesystem::path root = std::filesystem::path(map_path).parent_path().parent_path();
  return (root / list.counts_file).string();
}

Result<CtsCounts> loadCtsCounts(const std::string& path) {
  RAYSPEC_TRY(const std::string text, readWholeFile(path, kMaxCtsMapBytes));
  CtsCounts counts;
  std::istringstream in(text);
  std::string line;
  const std::string commit_tag = "VK-GL-CTS commit ";
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') {
      const size_t at = line.find(commit_tag);
      if (at != std::string::npos && counts.commit.empty())
        counts.commit = line.substr(at + commit_tag.size(), 40);
      continue;
    }
    std::istringstream fields(line);
    long n = 0;
    std::string group;
    if (!(fields >> n >> group)) continue;
    if (group == "total")
      counts.total = n;
    else
      counts.tests[group] = n;
  }
  if (counts.commit.size() != 40) return errorMessage(path + ": no 'VK-GL-CTS commit SHA' comment");
  if (counts.total == 0) return errorMessage(path + ": no 'COUNT total' line");
  return counts;
}

std::vector<std::string> ctsMapProblems(const CtsList& list, const CtsCounts& counts) {
  std::vector<std::string> out;
  std::set<std::string> named;
  for (const CtsGroup& g : list.groups) {
    if (!named.insert(g.group).second) out.push_back(list.name + "." + g.group + ": twice");
    if (!counts.tests.count(g.group))
      out.push_back(list.name + "." + g.group + ": not a group of " + list.counts_file);
  }
  long sum = 0;
  for (const auto& [group, n] : counts.tests) {
    sum += n;
    if (!named.count(group))
      out.push_back(list.name + "." + group + ": counted in " + list.counts_file + ", not mapped");
  }
  if (sum != counts.total)
    out.push_back(list.counts_file + ": the groups sum to " + std::to_string(sum) +
                  ", the total line says " + std::to_string(counts.total));
  return out;
}

std::string ctsSectionBegin(const CtsList& list) {
  return "<!-- cts-map " + list.name +
         ": begin (generated from references/cts-map.yaml: rayspec list --cts-map) -->";
}

std::string ctsSectionEnd(const CtsList& list) {
  return "<!-- cts-map " + list.name + ": end -->";
}

std::string ctsListSection(const CtsList& list, const CtsCounts& counts) {
  std::ostringstream out;
  out << list.groups.size() << " groups, " << counts.total << " tests in the mustpass list ("
      << list.mustpass << " at VK-GL-CTS " << counts.commit.substr(0, 7) << ", counted in "
      << list.counts_file << "). A group is full when every axis has a case, partial when "
      << "some has, none when none has:\n\n"
      << totalsTable(list, counts) << "\n"
      << "| CTS group | tests | coverage | what the CTS varies, and the cases and paths that "
         "cover it |\n|---|---|---|---|\n";
  for (const CtsGroup& g : list.groups) {
    const auto it = counts.tests.find(g.group);
    out << groupRow(g, it == counts.tests.end() ? 0 : it->second);
  }
  return out.str();
}

Result<std::string> ctsMapDocument(const std::string& doc, const std::vector<CtsList>& lists,
                                   const std::vector<std::string>& sections) {
  std::string out = doc;
  for (size_t i = 0; i < lists.size() && i < sections.size(); ++i) {
    RAYSPEC_TRY(out, withGeneratedPart(out, ctsSectionBegin(lists[i]), ctsSectionEnd(lists[i]),
                                       sections[i]));
  }
  return out;
}

}  // namespace rayspec
