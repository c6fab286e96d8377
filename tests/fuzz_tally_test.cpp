// The fuzzer's triage: which outcomes the checks refused, which are
// rayspec's own defects, which are findings; the known classes file; the
// tally's counts apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fuzz/fuzz_tally.h"
#include "fuzz/known_classes.h"

namespace rayspec {
namespace {

CaseOutcome outcomeOf(Status status, const std::string& rule, const std::string& message) {
  CaseOutcome o;
  o.name = "fuzz/seed-7";
  o.verdict.add({status, rule, message, {}, 0});
  o.deriveFromVerdict();
  return o;
}

TEST(FuzzTriage, ClassesOfOutcomes) {
  EXPECT_EQ(classify(outcomeOf(Status::CaseError, "R-UB", "the case has undefined behaviour")),
            FuzzClass::Refused);
  EXPECT_EQ(classify(outcomeOf(Status::CaseError, "R-ORDER-UNSPEC", "order-dependent: x")),
            FuzzClass::Refused);
  EXPECT_EQ(classify(outcomeOf(Status::CaseError, "case-file", "x.yaml:3:4: bad")),
            FuzzClass::Refused);
  // A shader rayspec wrote that does not compile, the model's crash: ours.
  EXPECT_EQ(classify(outcomeOf(Status::CaseError, "generated-shader", "vulkan: invalid")),
            FuzzClass::RayspecDefect);
  EXPECT_EQ(classify(outcomeOf(Status::Crash, "", "model: crashed (signal 11)")),
            FuzzClass::RayspecDefect);
  EXPECT_EQ(classify(outcomeOf(Status::Crash, "", "vulkan: crashed (signal 11)")),
            FuzzClass::Finding);
  EXPECT_EQ(classify(outcomeOf(Status::Fail, "R-BUILTIN", "per-ray field 'hit' differs")),
            FuzzClass::Finding);
  EXPECT_EQ(classify(outcomeOf(Status::NotSupported, "", "no feature")), FuzzClass::NotSupported);
}

TEST(FuzzTriage, SignatureTakesTheNumbersOut) {
  const FuzzSignature a = signatureOf(
      outcomeOf(Status::Fail, "R-BUILTIN", "counter 'chit' (exact): device 0, model 3"));
  const FuzzSignature b = signatureOf(
      outcomeOf(Status::Fail, "R-BUILTIN", "counter 'chit' (exact): device 2, model 1"));
  const FuzzSignature c = signatureOf(
      outcomeOf(Status::Fail, "R-BUILTIN", "counter 'miss' (exact): device 2, model 1"));
  EXPECT_EQ(a.folder, b.folder);
  EXPECT_NE(a.folder, c.folder);
  EXPECT_EQ(a.folder.find_first_not_of(
                "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_"),
            std::string::npos);
}

TEST(FuzzTriage, KnownClassesCountApart) {
  const std::vector<KnownClass> known = {{"nan-box", "a NaN box hides others"}};
  FuzzTally t;
  const CaseOutcome fail = outcomeOf(Status::Fail, "R-BUILTIN", "counter 'chit' (exact): 0, 1");
  const FuzzTally::Group* g = t.add(3, fail, knownClassOf(known, {"aabbs", "nan-box"}));
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->known, "nan-box: a NaN box hides others");
  EXPECT_EQ(g->signature.folder.rfind("known_nan-box_Fail_", 0), 0u) << g->signature.folder;
  EXPECT_EQ(t.add(4, fail, knownClassOf(known, {"nan-box"})), nullptr);  // the same group
  EXPECT_EQ(t.findingCases(true), 2u);
  EXPECT_EQ(t.findingCases(false), 0u);
  ASSERT_NE(t.add(5, fail, knownClassOf(known, {"aabbs"})), nullptr);  // new
  EXPECT_EQ(t.findingCases(false), 1u);
  t.add(6, outcomeOf(Status::CaseError, "R-UB", "undefined"), nullptr);
  EXPECT_EQ(t.refused, 1u);
  EXPECT_EQ(t.run, 4u);
  EXPECT_NE(t.text().find("1 cases new, 2 cases of known classes"), std::string::npos) << t.text();
}

TEST(FuzzTriage, KnownClassFileErrorsNameTheLine) {
  const std::string path = ::testing::TempDir() + "/fuzz-known.txt";
  std::ofstream(path) << "# comment\nnan-box the NaN box bug\nnan-boxes typo\n";
  const Result<std::vector<KnownClass>> bad = loadKnownClasses(path);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().format().find(":3:1: feature:"), std::string::npos) << bad.error().format();
  std::ofstream(path) << "nan-vertex\n";
  ASSERT_FALSE(loadKnownClasses(path));
  std::ofstream(path) << "nan-box the NaN box bug\n  nan-vertex  a NaN vertex\n";
  const Result<std::vector<KnownClass>> good = loadKnownClasses(path);
  ASSERT_TRUE(good) << good.error().format();
  ASSERT_EQ(good->size(), 2u);
  EXPECT_EQ((*good)[1].feature, "nan-vertex");
  EXPECT_EQ((*good)[1].reason, "a NaN vertex");
  std::filesystem::remove(path);
}

TEST(FuzzTriage, TheLavapipeKnownFileLoads) {
  const Result<std::vector<KnownClass>> known =
      loadKnownClasses(RAYSPEC_SOURCE_DIR "/references/baselines/lavapipe-fuzz-known.txt");
  ASSERT_TRUE(known) << known.error().format();
  // nan-box, nan-vertex, first-vertex, hit-builtin-after-trace, miss-world-ray-beside-empty-group
  EXPECT_EQ(known->size(), 5u);
}

TEST(FuzzTriage, TheMesa26KnownFileLoads) {
  const Result<std::vector<KnownClass>> known =
      loadKnownClasses(RAYSPEC_SOURCE_DIR "/references/baselines/mesa26-fuzz-known.txt");
  ASSERT_TRUE(known) << known.error().format();
  // nan-vertex, nan-box, inactive-instance, hit-builtin-after-trace,
  // miss-world-ray-beside-empty-group
  ASSERT_EQ(known->size(), 5u);
  for (const KnownClass& k : *known)
    EXPECT_NE(k.reason.find("references/driver-reports/"), std::string::npos) << k.feature;
}

}  // namespace
}  // namespace rayspec
