// Case names (results/file_name.h): caseNameFor gives a case name for any
// name, the one it was when it was one.
#include <gtest/gtest.h>

#include <string>

#include "results/file_name.h"

namespace rayspec {
namespace {

TEST(CaseNameFor, AnyNameGetsACaseNameAndACaseNameKeepsItsOwn) {
  EXPECT_EQ(caseNameFor("fam/a-b_c.1"), "fam/a-b_c.1");
  EXPECT_EQ(caseNameFor("fam/my case"), "fam/my_x20case");
  EXPECT_EQ(caseNameFor("fam/bad\xff"), "fam/bad_xFF");
  EXPECT_EQ(caseNameFor("fam/e/"), "fam/e/_");
  EXPECT_EQ(caseNameFor("../x"), "_x2E_x2E/x");
  EXPECT_EQ(caseNameFor("/abs"), "_/abs");
  EXPECT_EQ(caseNameFor(""), "_");
  const std::string hostile[] = {"a/./b",
                                 "x\ny",
                                 std::string("nul\0byte", 8),
                                 std::string(300, ' '),
                                 std::string(100, 'a') + "\xc3\xa9",
                                 "\xef\xbb\xbf"
                                 "bom",
                                 "a//b",
                                 "trailing/"};
  for (const std::string& name : hostile) {
    const std::string stand_in = caseNameFor(name);
    EXPECT_EQ(caseNameProblem(stand_in), "") << stand_in;
    EXPECT_EQ(caseNameFor(name), stand_in) << "the same every time";
  }
}

}  // namespace
}  // namespace rayspec
