// Where the copy and the structure queries come in the order of a level's
// build and updates (case/build_order.h), the one rule the Vulkan builds and
// the C export's player follow.
#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include "case/build_order.h"

namespace rayspec {
namespace {

// A scene updated `updates` times, copied as `copy` after `before` of them
// (none: every update first), its structures queried where `queried`.
Scene sceneOf(size_t updates, AsCopy copy, std::optional<uint32_t> before, bool queried) {
  Scene s;
  for (size_t k = 0; k < updates; ++k) s.earlier.push_back(std::make_shared<Scene>());
  s.build.copy = copy;
  s.build.updates_before_copy = before;
  if (queried) s.build.queries.queries = {StructureQuery::CompactedSize};
  return s;
}

TEST(BuildOrder, TheCopyComesAfterTheUpdatesBeforeItOrNever) {
  EXPECT_EQ(copyAt(sceneOf(0, AsCopy::None, {}, false)), 1u);
  EXPECT_EQ(copyAt(sceneOf(3, AsCopy::None, 1, false)), 4u);
  EXPECT_EQ(copyAt(sceneOf(0, AsCopy::Clone, {}, false)), 0u);
  EXPECT_EQ(copyAt(sceneOf(3, AsCopy::Compact, {}, false)), 3u);
  EXPECT_EQ(copyAt(sceneOf(3, AsCopy::Serialize, 1, false)), 1u);
  EXPECT_EQ(copyAt(sceneOf(2, AsCopy::Clone, 7, false)), 2u);  // at most every update
}

TEST(BuildOrder, TheQueriesComeJustBeforeTheCopyOrAfterTheLastUpdate) {
  EXPECT_EQ(queryAt(sceneOf(2, AsCopy::Clone, 1, false)), 3u);  // none asked: never
  EXPECT_EQ(queryAt(sceneOf(0, AsCopy::None, {}, true)), 0u);
  EXPECT_EQ(queryAt(sceneOf(3, AsCopy::None, 1, true)), 3u);
  EXPECT_EQ(queryAt(sceneOf(3, AsCopy::Clone, 1, true)), 1u);
  EXPECT_EQ(queryAt(sceneOf(3, AsCopy::Compact, {}, true)), 3u);
}

}  // namespace
}  // namespace rayspec
