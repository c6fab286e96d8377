// The rule catalog as a reader of the checkout needs it: every rule of
// references/spec-rules.yaml with its title, its text and the section of the
// specification it comes from; a rule map read with file, line and field.
#include <gtest/gtest.h>

#include <fstream>

#include "report/rule_catalog.h"
#include "test_dir.h"

namespace rayspec {
namespace {

TEST(RuleCatalogText, EveryRuleHasItsTextAndItsSection) {
  const auto rules = loadRuleCatalog(RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml");
  ASSERT_TRUE(rules) << rules.error().format();
  EXPECT_GE(rules->size(), 60u);
  for (const Rule& r : *rules) {
    EXPECT_FALSE(r.title.empty()) << r.label;
    EXPECT_GE(r.text.size(), r.title.size() / 2) << r.label << ": no text";
    EXPECT_GE(r.text.size(), 40u) << r.label << ": " << r.text;
    EXPECT_TRUE(r.spec.rfind("Vulkan, ", 0) == 0 || r.spec.rfind("SPIR-V", 0) == 0 ||
                r.spec.rfind("GLSL_EXT_", 0) == 0 || r.spec.rfind("GLSL_NV_", 0) == 0)
        << r.label << ": no specification section: '" << r.spec << "'";
  }
}

TEST(RuleCatalogText, ARuleMapIsReadWithItsFields) {
  const std::string path = testing_support::testDir() + "/catalog-rule-map.yaml";
  std::ofstream(path) << "R-ONE:\n  title: first\n  text: what it requires\n  spec: Vulkan, X\n"
                         "R-TWO: second\n";
  const auto rules = loadRuleCatalog(path);
  ASSERT_TRUE(rules) << rules.error().format();
  ASSERT_EQ(rules->size(), 2u);
  EXPECT_EQ((*rules)[0].title, "first");
  EXPECT_EQ((*rules)[0].text, "what it requires");
  EXPECT_EQ((*rules)[0].spec, "Vulkan, X");
  EXPECT_EQ((*rules)[1].title, "second") << "a catalog of titles only still reads";
  EXPECT_EQ((*rules)[1].text, "");
  std::ofstream(path) << "R-ONE:\n  title: first\n  txet: typo\n";
  const auto typo = loadRuleCatalog(path);
  ASSERT_FALSE(typo);
  EXPECT_EQ(typo.error().format().rfind(path + ":3:3: R-ONE.txet: unknown field", 0), 0u)
      << typo.error().format();
  std::ofstream(path) << "R-ONE:\n  text: no title\n";
  const auto untitled = loadRuleCatalog(path);
  ASSERT_FALSE(untitled);
  EXPECT_NE(untitled.error().format().find("R-ONE.title: missing the title"), std::string::npos)
      << untitled.error().format();
}

}  // namespace
}  // namespace rayspec
