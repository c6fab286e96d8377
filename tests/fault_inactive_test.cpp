// inactive-hides-last-active (Mesa 26.2.6 lavapipe's regression) on the cases
// that isolate it, the model's exact tier as the device: every variant with
// an inactive object before an active one fails, the *-last controls (inactive
// after every active one) are untouched by it and pass.
#include <gtest/gtest.h>

#include "planted_suite_case.h"

namespace rayspec {
namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(InactiveHidesLastActive, FailsEveryIsolatingCaseButTheControls) {
  size_t failed = 0, controls = 0;
  for (const CaseFile& f : findCases(kSuiteCases, "inactive/before-active-*")) {
    const std::optional<SuiteModelRun> run = suiteModelRun(f);
    ASSERT_TRUE(run);
    ASSERT_EQ(perfectStatus(*run), Status::Pass) << f.name;
    const auto [planted, v] = plantOnModel(*run, "inactive-hides-last-active");
    if (endsWith(f.name, "-last")) {
      EXPECT_FALSE(planted.applied) << f.name << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Pass) << f.name << ": " << v.headline();
      ++controls;
    } else {
      EXPECT_TRUE(planted.applied) << f.name << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Fail) << f.name << ": " << planted.what;
      failed += v.status == Status::Fail;
    }
  }
  EXPECT_EQ(controls, 4u * 2u);
  EXPECT_EQ(failed, 4u * 5u);
}

// The same fault on the seed chapter's hand-written cases that show it on
// Mesa 26.2.6 (null-instance: instance 3 lost; nan-x-triangle: primitive 2).
TEST(InactiveHidesLastActive, FailsTheSeedCasesItBreaksOnLavapipe26) {
  for (const char* name :
       {"inactive/null-instance", "inactive/nan-x-triangle", "inactive/nan-min-x-aabb"}) {
    const std::optional<SuiteModelRun> run = suiteModelRun(name);
    ASSERT_TRUE(run) << name;
    const auto [planted, v] = plantOnModel(*run, "inactive-hides-last-active");
    EXPECT_TRUE(planted.applied) << name;
    EXPECT_EQ(v.status, Status::Fail) << name << ": " << planted.what;
  }
}

// accel/update-inactive (inactive and degenerate primitives inside an
// update): the perfect device passes; a device whose update ignores it,
// revives the inactive primitives, or left the degenerate ones out for good
// fails each variant. Without an update, update-degenerate-lost changes nothing.
TEST(UpdateInactive, EachFaultOfAnUpdateFailsTheCase) {
  size_t cases = 0;
  for (const CaseFile& f : findCases(kSuiteCases, "accel/update-inactive/*")) {
    const std::optional<SuiteModelRun> run = suiteModelRun(f);
    ASSERT_TRUE(run);
    ASSERT_EQ(perfectStatus(*run), Status::Pass);
    for (const char* fault : {"update-ignored", "inactive-revived", "update-degenerate-lost"}) {
      const auto [planted, v] = plantOnModel(*run, fault);
      EXPECT_TRUE(planted.applied) << f.name << " " << fault << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Fail) << f.name << " " << fault << ": " << planted.what;
    }
    ++cases;
  }
  EXPECT_EQ(cases, 2u);
  const std::optional<SuiteModelRun> built = suiteModelRun("inactive/degenerate-triangles");
  ASSERT_TRUE(built);
  EXPECT_FALSE(plantOnModel(*built, "update-degenerate-lost").fault.applied);
}

}  // namespace
}  // namespace rayspec
