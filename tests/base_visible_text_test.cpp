// base/visible_text.h: the one rule for text from input that a message, a
// report or the console shows.
#include <gtest/gtest.h>

#include "base/visible_text.h"
#include "hostile_text.h"

namespace rayspec {
namespace {

using testing_support::kHostileText;
using testing_support::obeyedText;

TEST(VisibleText, ControlBytesAndNonAsciiAreShownAsHex) {
  EXPECT_EQ(visibleText("a\x1b[2Jb\x07\xc3\xa9"), "a\\x1B[2Jb\\x07\\xC3\\xA9");
  EXPECT_EQ(visibleText("line one\n\tline two"), "line one\n\tline two");
  EXPECT_EQ(visibleText("abcdef", 3), "abc... (6 bytes)");
}

// A field of a line: a line break in it is shown, not obeyed, and so is a ':'
// it begins with, so that no line of the output is a workflow command.
TEST(VisibleLine, AFieldNeverStartsALineNorACommand) {
  const std::string shown = visibleLine(kHostileText);
  EXPECT_EQ(
      shown,
      "dev\\x1B]52;c;cHduZWQ=\\x07\\x1B]0;title\\x07\\x1B[2J\\x0D\\x0A::error file=x::forged");
  EXPECT_EQ(obeyedText(shown), "");
  EXPECT_EQ(obeyedText("  " + visibleLine("  ::error file=x::forged")), "");
  EXPECT_EQ(visibleLine("::error"), "\\x3A:error");
  EXPECT_EQ(visibleLine(" \t:x"), " \t\\x3Ax");
  EXPECT_EQ(visibleLine("R-X: a: b"), "R-X: a: b") << "a ':' inside is left alone";
  EXPECT_EQ(visibleLine("a\tb"), "a\tb");
  EXPECT_EQ(visibleLine(""), "");
  // The check itself sees what it must.
  EXPECT_NE(obeyedText(kHostileText), "");
  EXPECT_NE(obeyedText("x\n   ::error file=x::y"), "");
}

}  // namespace
}  // namespace rayspec
