// scene.build.queries and query_command (case/structure_queries.h): the
// queries a case asks for, in its order, and the command; each error at its
// field.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

ParseResult parseQueries(const std::string& build) {
  return parseCaseText(oneTriangleText("R-AS-QUERY-SIZE", build, ""), "t.yaml", "t/t");
}

TEST(StructureQueriesField, QueriesAndCommandAreRead) {
  const ParseResult r =
      parseQueries("{queries: [size, bottom_level_pointers, compacted_size], query_command: host}");
  ASSERT_TRUE(r.value) << firstError(r);
  const StructureQueries& q = r.value->scene.build.queries;
  EXPECT_EQ(q.queries,
            (std::vector<StructureQuery>{StructureQuery::Size, StructureQuery::BottomLevelPointers,
                                         StructureQuery::CompactedSize}));
  EXPECT_EQ(q.command, QueryCommand::Host);
  EXPECT_TRUE(q.needsMaintenance1());
  EXPECT_FALSE(q.asks(StructureQuery::SerializationSize));
  const ParseResult none = parseQueries("{}");
  ASSERT_TRUE(none.value) << firstError(none);
  EXPECT_TRUE(none.value->scene.build.queries.queries.empty());
  EXPECT_EQ(none.value->scene.build.queries.command, QueryCommand::Device);
  const ParseResult compacted = parseQueries("{queries: [compacted_size, serialization_size]}");
  ASSERT_TRUE(compacted.value) << firstError(compacted);
  EXPECT_FALSE(compacted.value->scene.build.queries.needsMaintenance1());
}

TEST(StructureQueriesField, ErrorsNameTheField) {
  struct Bad {
    std::string build, field, message;
  } bad[] = {{"{queries: [compacted]}", "scene.build.queries[0]", "unknown query 'compacted'"},
             {"{queries: [size, size]}", "scene.build.queries[1]", "named twice"},
             {"{queries: size}", "scene.build.queries", ""},
             {"{queries: [size], query_command: gpu}", "scene.build.query_command",
              "unknown query command 'gpu' (device, host)"},
             {"{query_command: host}", "scene.build.query_command", "no scene.build.queries"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseQueries(b.build);
    EXPECT_FALSE(r.value) << b.build;
    const std::string e = firstError(r);
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

// The bottom levels each top level's instances reference: the model's part
// of R-AS-SERIAL-POINTERS, from the scene alone (null instances none).
TEST(StructureQueriesField, ReferencedBlasesComeFromTheInstances) {
  const Case c = parsedCase(
      "rules: [R-AS-SERIAL-POINTERS]\n"
      "scene:\n"
      "  blas:\n"
      "    a: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "    b: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "    c: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: b}, {blas: b}, {blas: null}, {blas: c, tlas: 1}]\n"
      "rays:\n"
      "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
  const std::vector<std::set<uint32_t>> levels = referencedBlases(c.scene);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0], (std::set<uint32_t>{1}));
  EXPECT_EQ(levels[1], (std::set<uint32_t>{2}));
}

}  // namespace
}  // namespace rayspec
