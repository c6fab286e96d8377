// `rayspec check` (mutate/case_portability.h, issue 61): the three mistakes
// of a new case writer (tests/data/not-portable: an aabb block that
// generates without testing its box, a candidate count declared exact, an
// any-hit count declared exact on a strip with edge rays) are each not
// portable, with the declaration to change at its line (an intersection
// program of a second hit group that reports without testing is blamed at
// its own); each fixed (tests/data/portable) is portable; and the diagnosis
// and the message of each kind of legal device (mutate/not_portable_cause.h).
#include <gtest/gtest.h>

#include "library/case_discovery.h"
#include "model_support.h"
#include "mutate/case_portability.h"

namespace rayspec {
namespace {

const std::string kData = RAYSPEC_SOURCE_DIR "/tests/data/";

Case loadDataCase(const std::string& path) {
  const std::vector<CaseFile> files = caseFilesFor(kData + path, kData);
  EXPECT_EQ(files.size(), 1u) << path;
  if (files.empty()) return Case{};
  const ParseResult p = loadCase(files.front(), kData);
  std::string errors;
  for (const Error& e : p.errors) errors += e.format() + "\n";
  EXPECT_TRUE(p.value && p.errors.empty()) << errors;
  return p.value ? *p.value : Case{};
}

// The problems of a case that must not be portable, each message in `text`.
std::vector<NotPortable> problemsOf(const std::string& path, std::string* text) {
  const CasePortability p = checkPortability(loadDataCase(path), 1);
  EXPECT_TRUE(p.checked) << p.not_checked;
  EXPECT_EQ(p.own_answers, "");
  EXPECT_FALSE(p.portable()) << path;
  *text = notPortableText(p);
  return p.problems;
}

bool hasDevice(const NotPortable& p, const std::string& name) {
  return p.device == name || std::find(p.also.begin(), p.also.end(), name) != p.also.end();
}

TEST(CasePortability, AnAabbBlockThatGeneratesWithoutTestingItsBoxIsNotPortable) {
  std::string text;
  const std::vector<NotPortable> problems =
      problemsOf("not-portable/box-report-untested.yaml", &text);
  ASSERT_EQ(problems.size(), 1u) << text;
  const NotPortable& p = problems[0];
  EXPECT_EQ(p.device, "aabb-neighbours");
  EXPECT_EQ(p.ray, 0);
  EXPECT_EQ(p.declaration.line, 28) << text;
  EXPECT_EQ(p.declaration.field, "pipeline.raygen[0].ray_query.aabb[0].generate");
  EXPECT_NE(p.change.find("without testing that the ray crosses its box"), std::string::npos);
  EXPECT_NE(text.find("box-report-untested.yaml:28:13: pipeline.raygen[0].ray_query.aabb[0]."
                      "generate: not portable: a device the specification allows "
                      "(aabb-neighbours"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("would fail ray 0 because R-RQ-COMMIT: per-ray field 'value1'"),
            std::string::npos)
      << text;
}

// The statement blamed is the one that reported for the box the ray misses
// (the device's run notes it: Results::missed_box_reports), not the first
// report of the pipeline (hit group 0's, which tests its box).
TEST(CasePortability, TheReportMadeForTheMissedBoxIsBlamed) {
  std::string text;
  const std::vector<NotPortable> problems =
      problemsOf("not-portable/box-report-in-second-group.yaml", &text);
  ASSERT_EQ(problems.size(), 1u) << text;
  const NotPortable& p = problems[0];
  EXPECT_TRUE(hasDevice(p, "aabb-neighbours")) << text;
  EXPECT_EQ(p.ray, 0) << text;
  EXPECT_EQ(p.declaration.line, 36) << text;
  EXPECT_EQ(p.declaration.field, "pipeline.hit_groups[1].intersection[0].report") << text;
  EXPECT_NE(p.change.find("without testing that the ray crosses its box"), std::string::npos);
}

TEST(CasePortability, ACandidateCountDeclaredExactIsNotPortable) {
  std::string text;
  const std::vector<NotPortable> problems = problemsOf("not-portable/candidates-exact.yaml", &text);
  ASSERT_EQ(problems.size(), 1u) << text;  // one declaration, every order that moves it
  const NotPortable& p = problems[0];
  EXPECT_TRUE(hasDevice(p, "reverse-order")) << text;
  EXPECT_EQ(p.declaration.line, 38) << text;
  EXPECT_EQ(p.declaration.field, "outputs.counters[0].candidates");
  EXPECT_NE(p.change.find("counter 'candidates' is declared `exact`"), std::string::npos);
  EXPECT_NE(p.change.find("`at_least`"), std::string::npos) << p.change;
  EXPECT_NE(p.change.find("leave its mode undeclared"), std::string::npos) << p.change;
}

TEST(CasePortability, AnAnyHitCountDeclaredExactOnEdgeRaysIsNotPortable) {
  std::string text;
  const std::vector<NotPortable> problems =
      problemsOf("not-portable/anyhit-exact-edges.yaml", &text);
  ASSERT_FALSE(problems.empty());
  bool counter = false;
  for (const NotPortable& p : problems)
    if (p.declaration.field == "outputs.counters[0].anyhit") {
      counter = true;
      EXPECT_EQ(p.declaration.line, 31);
      EXPECT_TRUE(hasDevice(p, "any-hit-runs-twice")) << text;
      EXPECT_NE(p.finding.find("counter 'anyhit' (exact)"), std::string::npos) << p.finding;
    }
  EXPECT_TRUE(counter) << text;
}

// A ray from far away at boxes whose programs test their inscribed spheres
// (case/huge_rays.h): refused at the ray's line, whatever the legal devices
// say; the same ray started near the boxes is accepted (EachMistakeFixedIsPortable).
TEST(CasePortability, AHugeRayAtASphereTestingBoxIsNotPortable) {
  std::string text;
  const std::vector<NotPortable> problems =
      problemsOf("not-portable/huge-ray-at-sphere-box.yaml", &text);
  ASSERT_FALSE(problems.empty());
  const NotPortable& p = problems.front();
  EXPECT_EQ(p.device, "object-ray-rounding") << text;
  EXPECT_EQ(p.ray, 1) << text;
  EXPECT_EQ(p.declaration.line, 20) << text;
  EXPECT_EQ(p.declaration.field, "rays.list[1]") << text;
  EXPECT_NE(text.find("huge-ray-at-sphere-box.yaml:20:7: rays.list[1]: not portable: a device "
                      "the specification allows (object-ray-rounding"),
            std::string::npos)
      << text;
  EXPECT_NE(p.finding.find("of geometry 0 of instance 0, whose intersection program (hit group "
                           "0) tests the sphere inscribed in the box"),
            std::string::npos)
      << p.finding;
  EXPECT_NE(p.change.find("start the ray nearer the boxes"), std::string::npos) << p.change;
}

TEST(CasePortability, EachMistakeFixedIsPortable) {
  for (const char* path :
       {"portable/box-report-tested.yaml", "portable/candidates-at-least.yaml",
        "portable/anyhit-undeclared-edges.yaml", "portable/near-ray-at-sphere-box.yaml"}) {
    const CasePortability p = checkPortability(loadDataCase(path), 1);
    EXPECT_TRUE(p.portable()) << path << ": " << p.not_checked << p.own_answers
                              << notPortableText(p);
    EXPECT_GT(p.devices, 0u) << path;
  }
  // The fixes are tested on devices that differ from the model there.
  EXPECT_GT(checkPortability(loadDataCase("portable/candidates-at-least.yaml"), 1).applied, 0u);
  EXPECT_GT(checkPortability(loadDataCase("portable/anyhit-undeclared-edges.yaml"), 1).applied, 0u);
}

TEST(CasePortability, ACaseTheModelFindsAtFaultIsNotJudgedByItsLegalDevices) {
  // An any-hit that accumulates into the payload on geometry without
  // no_duplicate_any_hit: the model's own answers are a CaseError
  // (R-AHIT-DUP), so no legal device is blamed.
  const Case c = model_test::parseInline(R"(rules: [R-AHIT-CLOSEST]
scene:
  blas:
    tri: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0.1, 0.2, 10], direction: [0, 0, -1]}]
  tmin: 0.001
  tmax: 100
pipeline:
  hit_groups:
    - any_hit: [payload: {value: {add: [payload.value, 1]}}]
      closest_hit: [record: {value: payload.value}]
outputs:
  per_ray: [value]
)");
  const CasePortability p = checkPortability(c, 1);
  EXPECT_TRUE(p.checked);
  EXPECT_NE(p.own_answers.find("R-AHIT-DUP"), std::string::npos) << p.own_answers;
  EXPECT_TRUE(p.problems.empty());
  EXPECT_FALSE(p.portable());
  EXPECT_EQ(notPortableText(p), "") << "the run judges such a case itself";
}

// ---- the diagnosis of each kind of legal device ----------------------------

// A ray query case with an any-hit pipeline beside it, parsed from text.
Case queryCase() {
  return model_test::parseInline(R"(rules: [R-RQ-COMMIT]
scene:
  blas:
    tri: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [0.1, 0.2, 10], direction: [0, 0, -1]}
    - {origin: [30, 0.2, 10], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - ray_query:
        triangle: [count: seen, confirm]
        after: [record: {value: committed.type}]
outputs:
  counters: [{seen: at_most}]
  per_ray: [value]
)",
                                 "portability/query");
}

// The causes of a legal device `name` that the judge fails with one
// finding (its rule, message and first ray).
std::vector<NotPortable> causesOf(const Case& c, const std::string& name, int64_t ray) {
  const Plan plan = derivePlan(c);
  Results model;
  model.records.assign(recordWords() * 2, 0);
  LegalVariant v{name, model, true, "what it does"};
  Verdict verdict;
  verdict.add({Status::Fail, "R-X", "something differs", {}, 0});
  if (ray >= 0) verdict.findings.back().rays = {static_cast<uint32_t>(ray)};
  return notPortableCauses(c, plan, model, model, v, verdict);
}

TEST(NotPortableCause, AnotherOrderNamesTheRayQueryAndOrderDependentTrue) {
  const Case c = queryCase();
  for (const char* device : {"reverse-order", "permuted-order-2", "last-0.0.0"}) {
    const std::vector<NotPortable> causes = causesOf(c, device, 0);
    ASSERT_EQ(causes.size(), 1u) << device;
    EXPECT_EQ(causes[0].declaration.field, "pipeline.raygen[0].ray_query") << device;
    EXPECT_EQ(causes[0].declaration.line, 14) << device;
    EXPECT_NE(causes[0].change.find("`order_dependent: true`"), std::string::npos);
    EXPECT_EQ(causes[0].finding, "R-X: something differs");
    EXPECT_EQ(causes[0].ray, 0);
  }
}

TEST(NotPortableCause, AnAmbiguousAnswerNamesTheRay) {
  const std::vector<NotPortable> causes = causesOf(queryCase(), "answer-1", 1);
  ASSERT_EQ(causes.size(), 1u);
  EXPECT_EQ(causes[0].declaration.field, "rays.list[1]");
  EXPECT_EQ(causes[0].declaration.line, 9);
  EXPECT_NE(causes[0].change.find("ambiguous"), std::string::npos);
}

TEST(NotPortableCause, AProgramRunTwiceNamesItsHitGroup) {
  Case c = model_test::parseInline(R"(rules: [R-AHIT-CLOSEST]
scene:
  blas:
    tri: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0.1, 0.2, 10], direction: [0, 0, -1]}]
  tmin: 0.001
  tmax: 100
pipeline:
  hit_groups:
    - any_hit: [count: anyhit]
      closest_hit: [record: {value: 1}]
outputs:
  counters: [anyhit]
  per_ray: [value]
)");
  const std::vector<NotPortable> causes = causesOf(c, "any-hit-runs-twice", -1);
  ASSERT_EQ(causes.size(), 1u);
  EXPECT_EQ(causes[0].declaration.field, "pipeline.hit_groups[0]");
  EXPECT_NE(causes[0].change.find("no_duplicate_any_hit"), std::string::npos);
  EXPECT_EQ(causes[0].ray, -1) << "no finding's ray, no record changed";
}

TEST(NotPortableCause, ADeclaredBoundMovedTheOtherWayNamesTheCounter) {
  const Case c = queryCase();
  const Plan plan = derivePlan(c);
  Results model;
  model.records.assign(recordWords() * 2, 0);
  model.counters["seen"] = 2;
  LegalVariant v{"reverse-order", model, true, "far to near"};
  v.device.counters["seen"] = 3;  // above the model's: at_most broken
  v.device.records[0] = 1;        // ray 0 changed
  Verdict verdict;
  verdict.add({Status::Fail, "R-X", "counter 'seen' (at_most): device 3, model 2", {}, 0});
  const std::vector<NotPortable> causes = notPortableCauses(c, plan, model, model, v, verdict);
  ASSERT_FALSE(causes.empty());
  EXPECT_EQ(causes[0].declaration.field, "outputs.counters[0].seen");
  EXPECT_EQ(causes[0].finding, "counter 'seen' (at_most): device 3, model 2");
  EXPECT_NE(causes[0].change.find("declared `at_most`"), std::string::npos) << causes[0].change;
  EXPECT_NE(causes[0].change.find("`informational`"), std::string::npos) << causes[0].change;
  EXPECT_EQ(causes[0].ray, 0) << "the first ray whose record the device changed";
}

// ---- the message ------------------------------------------------------------

NotPortable sample() {
  NotPortable p;
  p.device = "aabb-neighbours";
  p.what = "boxes grown";
  p.ray = 3;
  p.finding = "R-RQ-COMMIT: per-ray field 'value' differs";
  p.declaration = {"cases/x.yaml", 12, 7, "pipeline.raygen[0]"};
  p.change = "test the box";
  return p;
}

TEST(NotPortableMessage, NamesFileLineFieldDeviceRayFindingAndChange) {
  EXPECT_EQ(notPortableMessage(sample()),
            "cases/x.yaml:12:7: pipeline.raygen[0]: not portable: a device the specification "
            "allows (aabb-neighbours: boxes grown) would fail ray 3 because R-RQ-COMMIT: "
            "per-ray field 'value' differs; test the box");
}

TEST(NotPortableMessage, WithoutALineNamesTheFileAndWithoutARayTheCase) {
  NotPortable p = sample();
  p.declaration = {"cases/x.yaml", 0, 0, ""};
  p.ray = -1;
  p.what = "";
  EXPECT_EQ(notPortableMessage(p),
            "cases/x.yaml: not portable: a device the specification allows (aabb-neighbours) "
            "would fail the case because R-RQ-COMMIT: per-ray field 'value' differs; test the "
            "box");
}

TEST(NotPortableMessage, NamesTheOtherDevicesAndShowsControlCharacters) {
  NotPortable p = sample();
  p.also = {"reverse-order", "last-0.0.1"};
  p.change = "test\x1b[31m the box";
  const std::string m = notPortableMessage(p);
  EXPECT_NE(m.find("(also reverse-order, last-0.0.1)"), std::string::npos) << m;
  EXPECT_EQ(m.find('\x1b'), std::string::npos) << "made visible (base/visible_text.h)";
}

TEST(NotPortableMessage, TheCaseErrorHoldsEveryProblemOneALine) {
  CasePortability p;
  p.checked = true;
  EXPECT_EQ(notPortableText(p), "");
  p.problems = {sample(), sample()};
  p.problems[1].ray = 4;
  const std::string text = notPortableText(p);
  EXPECT_EQ(text, notPortableMessage(p.problems[0]) + "\n  " + notPortableMessage(p.problems[1]));
}

// The model's own answers as a device failing the case (not by a CaseError,
// which the run gives itself): the check refuses it with that reason, where
// it let it through before (fuzz/seed-150445 and 150663 on Mesa 26.2.6:
// `rayspec show` said NOT PORTABLE, `rayspec fuzz` ran and failed them).
TEST(NotPortableMessage, TheModelFailingItsOwnAnswersRefusesTheCase) {
  CasePortability p;
  p.checked = true;
  p.own_answers = "Fail R-TOFH: numerically ambiguous ray (first-hit) missed (1 rays; first: 6)";
  p.own_status = Status::Fail;
  const std::string text = notPortableText(p);
  EXPECT_NE(text.find("the model's own answers, as a device, do not pass"), std::string::npos)
      << text;
  EXPECT_NE(text.find(p.own_answers), std::string::npos) << text;
  p.own_status = Status::CaseError;  // the run gives it, by its own rule
  EXPECT_EQ(notPortableText(p), "");
}

}  // namespace
}  // namespace rayspec
