// scene.build.queries and scene.build.query_command (case/structure_queries.h).
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

// One name of scene.build.queries, once.
void parseQueryName(YamlReader& r, const YAML::Node& v, const std::string& field,
                    StructureQueries& q) {
  const auto name = r.string(v, field);
  if (!name) return;
  const auto query = valueNamed<StructureQuery>(*name);
  if (!query)
    r.error(v, field,
            "unknown query '" + *name + "' (" + namesJoined(enumNames<StructureQuery>()) + ")");
  else if (q.asks(*query))
    r.error(v, field, "query '" + *name + "' named twice");
  else
    q.queries.push_back(*query);
}

}  // namespace

void parseStructureQueries(YamlReader& r, const YAML::Node& n, AsBuild& build) {
  const std::string f = "scene.build.queries";
  if (auto v = YamlReader::get(n, "queries"); v.IsDefined() && r.expectSeq(v, f))
    for (size_t i = 0; i < v.size(); ++i)
      parseQueryName(r, v[i], f + "[" + std::to_string(i) + "]", build.queries);
  const YAML::Node command = YamlReader::get(n, "query_command");
  if (!command.IsDefined()) return;
  const auto name = r.string(command, "scene.build.query_command");
  if (!name) return;
  if (const auto c = valueNamed<QueryCommand>(*name))
    build.queries.command = *c;
  else
    r.error(
        command, "scene.build.query_command",
        "unknown query command '" + *name + "' (" + namesJoined(enumNames<QueryCommand>()) + ")");
  if (build.queries.queries.empty())
    r.error(command, "scene.build.query_command", "no scene.build.queries to make");
}

}  // namespace rayspec
