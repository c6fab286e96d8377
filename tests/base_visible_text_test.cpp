// base/visible_text.h: text from input as a message may quote it; one
// visible line where it becomes a line of a file or of the console.
#include <gtest/gtest.h>

#include "base/visible_text.h"

namespace rayspec {
namespace {

TEST(VisibleText, KeepsLinesEscapesTheRest) {
  EXPECT_EQ(visibleText("a\tb\nc\x1b[2J\xc3\xa9"), "a\tb\nc\\x1B[2J\\xC3\\xA9");
  EXPECT_EQ(visibleText("abcdef", 3), "abc... (6 bytes)");
}

TEST(VisibleText, ALineHoldsNoLineBreak) {
  EXPECT_EQ(visibleLine("note\nfam/victim,Fail\r\n\tx"),
            "note\\x0Afam/victim,Fail\\x0D\\x0A\\x09x");
  EXPECT_EQ(visibleLine("plain, ascii (1)"), "plain, ascii (1)");
  // Read back and escaped again, a line stays as it was.
  EXPECT_EQ(visibleLine(visibleLine("a\nb")), visibleLine("a\nb"));
}

}  // namespace
}  // namespace rayspec
