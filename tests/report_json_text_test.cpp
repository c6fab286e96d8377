// JSON as text (report/json_text.h): nlohmann-json's exception on text that
// is not UTF-8 becomes an Input error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report/json_text.h"

namespace rayspec {
namespace {

TEST(JsonText, WritesWhatNlohmannWritesAndSaysWhyNot) {
  const nlohmann::json good = {{"name", "fam/a"}, {"n", 2}};
  const Result<std::string> text = jsonText(good, 1);
  ASSERT_TRUE(text) << text.error().format();
  EXPECT_EQ(*text, good.dump(1));
  const Result<std::string> bad = jsonText(nlohmann::json{{"name", "fam/\xff"}});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().kind, ErrorKind::Input);
  EXPECT_NE(bad.error().message.find("UTF-8"), std::string::npos) << bad.error().message;
}

}  // namespace
}  // namespace rayspec
