// pipeline.libraries: a list of pipeline libraries, each
//   {miss: [i, ...], hit_groups: [i, ...], callables: [i, ...], libraries: [...]}
// naming the groups it holds (indices into pipeline.miss / hit_groups /
// callables) and the libraries it links in turn. Every index must exist and
// sit in at most one library; a library must hold a group or a library.
#include <set>

#include "parse/parse_parts.h"

namespace rayspec {
namespace {

struct LibraryParser {
  YamlReader& r;
  const Pipeline& p;
  std::set<std::pair<std::string, uint32_t>> placed;  // (kind, index)
  size_t count = 0;

  void indices(const YAML::Node& n, const std::string& field, const std::string& kind, size_t size,
               std::vector<uint32_t>& out) {
    if (!r.expectSeq(n, field)) return;
    for (size_t i = 0; i < n.size(); ++i) {
      const std::string fi = field + "[" + std::to_string(i) + "]";
      const std::optional<uint32_t> index = r.uint(n[i], fi);
      if (!index) continue;
      if (*index >= size)
        r.error(n[i], fi,
                "pipeline." + kind + " has " + std::to_string(size) + " entries, no " +
                    std::to_string(*index));
      else if (!placed.insert({kind, *index}).second)
        r.error(n[i], fi,
                "pipeline." + kind + "[" + std::to_string(*index) + "] is already in a library");
      else
        out.push_back(*index);
    }
  }

  void library(const YAML::Node& n, const std::string& field, PipelineLibrary& lib) {
    lib.loc = r.loc(n, field);
    if (++count > kMaxPipelineLibraries) {
      r.error(n, field, "more than " + std::to_string(kMaxPipelineLibraries) + " libraries");
      return;
    }
    if (!r.expectMap(n, field, {"miss", "hit_groups", "callables", "libraries"})) return;
    if (auto v = YamlReader::get(n, "miss"); v.IsDefined())
      indices(v, field + ".miss", "miss", p.miss.size(), lib.miss);
    if (auto v = YamlReader::get(n, "hit_groups"); v.IsDefined())
      indices(v, field + ".hit_groups", "hit_groups", p.hit_groups.size(), lib.hit_groups);
    if (auto v = YamlReader::get(n, "callables"); v.IsDefined())
      indices(v, field + ".callables", "callables", p.callables.size(), lib.callables);
    if (auto v = YamlReader::get(n, "libraries"); v.IsDefined())
      list(v, field + ".libraries", lib.libraries);
    if (lib.miss.empty() && lib.hit_groups.empty() && lib.callables.empty() &&
        lib.libraries.empty())
      r.error(n, field, "a library holds at least one group or library");
  }

  void list(const YAML::Node& n, const std::string& field, std::vector<PipelineLibrary>& out) {
    if (!r.expectSeq(n, field)) return;
    for (size_t i = 0; i < n.size(); ++i) {
      PipelineLibrary lib;
      library(n[i], field + "[" + std::to_string(i) + "]", lib);
      out.push_back(std::move(lib));
    }
  }
};

}  // namespace

void parseLibraries(YamlReader& r, const YAML::Node& n, Pipeline& pipeline) {
  LibraryParser parser{r, pipeline, {}, 0};
  parser.list(n, "pipeline.libraries", pipeline.libraries);
}

}  // namespace rayspec
