#include "base/enum_names.h"

#include <gtest/gtest.h>

#include <string>

namespace rayspec {

#define RAYSPEC_TEST_FRUITS(X) X(Apple, "apple", 3) X(Pear, "pear", 5) X(PlumTree, "plum-tree", 8)
enum class TestFruit { RAYSPEC_TEST_FRUITS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(TestFruit, RAYSPEC_TEST_FRUITS);

TEST(EnumNames, EveryEnumeratorHasTheNameOfItsRow) {
  EXPECT_EQ(enumCount<TestFruit>(), 3u);
  EXPECT_STREQ(nameOf(TestFruit::Apple), "apple");
  EXPECT_STREQ(nameOf(TestFruit::PlumTree), "plum-tree");
  EXPECT_STREQ(nameOf(static_cast<TestFruit>(7)), "?");  // a value cast from bad data
}

TEST(EnumNames, NamesReadBackToTheirValueAndNothingElseDoes) {
  for (TestFruit f : enumValues<TestFruit>()) EXPECT_EQ(valueNamed<TestFruit>(nameOf(f)), f);
  EXPECT_FALSE(valueNamed<TestFruit>("Apple").has_value());  // names are case-sensitive
  EXPECT_FALSE(valueNamed<TestFruit>("").has_value());
  TestFruit out = TestFruit::Apple;
  EXPECT_TRUE(parseEnumName("pear", &out));
  EXPECT_EQ(out, TestFruit::Pear);
  EXPECT_FALSE(parseEnumName("plum", &out));
  EXPECT_EQ(out, TestFruit::Pear);  // untouched on failure
}

TEST(EnumNames, NamesJoinedInListOrder) {
  EXPECT_EQ(namesJoined(enumNames<TestFruit>()), "apple, pear, plum-tree");
  EXPECT_EQ(namesJoined(enumNames<TestFruit>(), " | "), "apple | pear | plum-tree");
}

TEST(EnumNames, ExtraColumnsStayTheListsOwn) {
#define RAYSPEC_TEST_FRUIT_SEEDS(id, name, seeds) seeds,
  constexpr int kSeeds[] = {RAYSPEC_TEST_FRUITS(RAYSPEC_TEST_FRUIT_SEEDS)};
#undef RAYSPEC_TEST_FRUIT_SEEDS
  EXPECT_EQ(kSeeds[static_cast<int>(TestFruit::PlumTree)], 8);
}

// A table whose rows are out of enum order is what enumRowsInOrder rejects
// (RAYSPEC_ENUM_NAMES static_asserts it).
TEST(EnumNames, RowsOutOfOrderAreRejected) {
  constexpr EnumName<TestFruit> swapped[] = {{TestFruit::Pear, "pear"},
                                             {TestFruit::Apple, "apple"}};
  static_assert(!enumRowsInOrder(std::span<const EnumName<TestFruit>>(swapped)));
  static_assert(enumRowsInOrder(enumNames<TestFruit>()));
  SUCCEED();
}

}  // namespace rayspec
