// The names of payload, callable data and attribute words (program/
// payload_words.h): word0 .. word57 in decimal, without leading zeros, and
// the built-ins that read them.
#include <gtest/gtest.h>

#include "program/ops.h"
#include "program/payload_words.h"

namespace rayspec {
namespace {

TEST(PayloadWords, WordNamesAreDecimalUpToTheLargestType) {
  EXPECT_EQ(payloadWordField("word0"), 0u);
  EXPECT_EQ(payloadWordField("word9"), 9u);
  EXPECT_EQ(payloadWordField("word10"), 10u);
  EXPECT_EQ(payloadWordField("word57"), kPayloadWordNames - 1);
  for (const char* bad : {"word58", "word99", "word100", "word07", "word00", "word", "word-1",
                          "word5x", "words1", "Word1", "word 1"})
    EXPECT_FALSE(payloadWordField(bad).has_value()) << bad;
}

TEST(PayloadWords, BuiltinsNameTheirPrefixAndWord) {
  const auto child = payloadWordBuiltin("child.word42");
  ASSERT_TRUE(child);
  EXPECT_TRUE(child->child);
  EXPECT_EQ(child->index, 42u);
  EXPECT_FALSE(payloadWordBuiltin("payload.word58"));
  const auto callee = callWordBuiltin("callee.word51");
  ASSERT_TRUE(callee);
  EXPECT_TRUE(callee->callee);
  EXPECT_EQ(callee->index, 51u);
  EXPECT_FALSE(callWordBuiltin("payload.word3"));
  // The attribute keeps its 32 bytes: words 0 .. 5.
  EXPECT_EQ(attributeWordBuiltin("attribute.word5"), 5u);
  EXPECT_FALSE(attributeWordBuiltin("attribute.word6"));
  EXPECT_FALSE(attributeWordBuiltin("attribute.word10"));
}

TEST(PayloadWords, IndexedArraysHaveOneNameEach) {
  for (WordArray w : {WordArray::Payload, WordArray::Child, WordArray::Call, WordArray::Callee}) {
    const std::string name = wordArrayName(w);
    // The op is the array's name with "s" dropped and "." as "_".
    const std::string op = name.substr(0, name.find('.')) + "_word";
    EXPECT_EQ(wordArrayOf(opNamed(op)), w) << op;
  }
  // Only the incoming data is written by a store.
  EXPECT_EQ(wordArrayOfStore("payload.words"), WordArray::Payload);
  EXPECT_EQ(wordArrayOfStore("call.words"), WordArray::Call);
  EXPECT_FALSE(wordArrayOfStore("child.words"));
  EXPECT_FALSE(wordArrayOfStore("callee.words"));
  EXPECT_FALSE(wordArrayOfStore("words"));
  EXPECT_FALSE(wordArrayOf(opNamed("payload.word")));
  EXPECT_FALSE(wordArrayOf(Op::Add));
}

}  // namespace
}  // namespace rayspec
