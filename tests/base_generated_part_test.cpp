// A document's generated part, replaced between its markers.
#include <gtest/gtest.h>

#include "base/generated_part.h"

namespace rayspec {
namespace {

TEST(GeneratedPart, TheTextBetweenTheMarkersIsReplaced) {
  const std::string doc = "head\n<!-- b -->\nold\nlines\n<!-- e -->\ntail <!-- e -->\n";
  const Result<std::string> made = withGeneratedPart(doc, "<!-- b -->", "<!-- e -->", "new\n");
  ASSERT_TRUE(made.ok());
  EXPECT_EQ(*made, "head\n<!-- b -->\nnew\n<!-- e -->\ntail <!-- e -->\n");
}

TEST(GeneratedPart, AMissingMarkerIsNamed) {
  for (const std::string doc : {"<!-- e --> then <!-- b -->", "<!-- b --> alone"}) {
    const Result<std::string> made = withGeneratedPart(doc, "<!-- b -->", "<!-- e -->", "x");
    ASSERT_FALSE(made.ok()) << doc;
    EXPECT_NE(made.error().message.find("<!-- b --> and <!-- e -->"), std::string::npos);
  }
}

}  // namespace
}  // namespace rayspec
