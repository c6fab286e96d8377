// `rayspec check` and `rayspec run --check-case` run as programs (issue 61):
// the three mistakes of tests/data/not-portable each reported not portable
// with the declaration to change, by check and by run (on by default for a
// case file outside cases/, which then does not run); each fixed
// (tests/data/portable) portable; a library case checked only when asked.
// The runs use --no-device: the check needs the model alone.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"

namespace {

const std::string kData = RAYSPEC_SOURCE_DIR "/tests/data/";
const std::string kNotPortable[] = {"box-report-untested", "candidates-exact",
                                    "anyhit-exact-edges"};
const std::string kPortable[] = {"box-report-tested", "candidates-at-least",
                                 "anyhit-undeclared-edges"};

struct Ran {
  int status = -1;
  std::string out;
};

// `rayspec ARGS`, stdout and stderr together.
Ran rayspec(const std::string& args, const std::string& dir) {
  const std::string log = dir + "/log.txt";
  Ran r;
  r.status = cli::sh(cli::kBin + " " + args, log);
  r.out = cli::slurp(log);
  return r;
}

// Each mistake's declaration to change, file:line:col and field, and what
// the message says to do instead.
struct Mistake {
  std::string name, where, change;
};
const Mistake kMistakes[] = {
    {"box-report-untested",
     "box-report-untested.yaml:28:13: pipeline.raygen[0].ray_query.aabb[0].generate: not portable: "
     "a device the specification allows (aabb-neighbours",
     "report only where the ray crosses the box"},
    {"candidates-exact",
     "candidates-exact.yaml:38:27: outputs.counters[0].candidates: not portable",
     "counter 'candidates' is declared `exact`, but a device the specification allows counts it "
     "more often than the model: declare it a bound (`at_least`) or leave its mode undeclared"},
    {"anyhit-exact-edges",
     "anyhit-exact-edges.yaml:31:23: outputs.counters[0].anyhit: not portable",
     "counter 'anyhit' is declared `exact`, but a device the specification allows counts it more "
     "often than the model: declare it a bound (`at_least`) or leave its mode undeclared"}};

// Each mistake named in `text` by its declaration and what to change there.
void expectEachDeclarationToChange(const std::string& text) {
  for (const Mistake& m : kMistakes) {
    EXPECT_NE(text.find(m.where), std::string::npos) << m.where << "\n" << text;
    EXPECT_NE(text.find(m.change), std::string::npos) << m.change << "\n" << text;
  }
}

std::string files(const std::string& folder, const std::string (&names)[3]) {
  std::string out;
  for (const std::string& n : names) out += " " + kData + folder + "/" + n + ".yaml";
  return out;
}

TEST(Check, EachMistakeIsNotPortableWithTheDeclarationToChange) {
  const std::string dir = cli::fresh("check/mistakes");
  const Ran r = rayspec("check --threads 1" + files("not-portable", kNotPortable), dir);
  EXPECT_EQ(r.status, 1) << r.out;
  for (const std::string& n : kNotPortable)
    EXPECT_NE(r.out.find("NOT PORTABLE  " + n), std::string::npos) << r.out;
  expectEachDeclarationToChange(r.out);
  EXPECT_NE(r.out.find("0 of 3 cases portable"), std::string::npos) << r.out;
}

TEST(Check, EachMistakeFixedIsPortable) {
  const std::string dir = cli::fresh("check/fixed");
  const Ran r = rayspec("check --threads 1" + files("portable", kPortable), dir);
  EXPECT_EQ(r.status, 0) << r.out;
  for (const std::string& n : kPortable)
    EXPECT_NE(r.out.find("portable      " + n + " ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("3 of 3 cases portable"), std::string::npos) << r.out;
}

TEST(Check, ACaseByNameAndBadInput) {
  const std::string dir = cli::fresh("check/input");
  const Ran named = rayspec("check ray-query/generate-at-tmin --threads 1", dir);
  EXPECT_EQ(named.status, 0) << named.out;
  EXPECT_NE(named.out.find("portable      ray-query/generate-at-tmin"), std::string::npos);
  const Ran missing = rayspec("check " + kData + "nope.yaml", dir);
  EXPECT_EQ(missing.status, 2) << missing.out;
  EXPECT_NE(missing.out.find("no such case file"), std::string::npos) << missing.out;
  const Ran bad = rayspec("check " + kData + "bad/unknown-key.yaml", dir);
  EXPECT_EQ(bad.status, 1) << bad.out;
  EXPECT_NE(bad.out.find("CaseError     unknown-key"), std::string::npos) << bad.out;
}

// A run of every file, mistakes and fixes: `flags` added.
Ran runAll(const std::string& dir, const std::string& flags) {
  std::string cases;
  for (const std::string& n : kNotPortable)
    cases += " --case " + kData + "not-portable/" + n + ".yaml";
  for (const std::string& n : kPortable) cases += " --case " + kData + "portable/" + n + ".yaml";
  return rayspec("run --no-device --threads 1 --out " + dir + "/out" + cases + flags, dir);
}

TEST(CheckCase, ARunChecksACaseOutsideTheLibraryAndRefusesAMistake) {
  const std::string dir = cli::fresh("check/run");
  const Ran r = runAll(dir, "");
  EXPECT_EQ(r.status, 1) << r.out;  // CaseErrors
  const std::string summary = cli::slurp(dir + "/out/summary.txt");
  for (const std::string& n : kNotPortable) {
    EXPECT_NE(r.out.find(n + ": checked against the devices the specification allows: not "
                             "portable"),
              std::string::npos)
        << r.out;
    EXPECT_NE(summary.find(n), std::string::npos) << summary;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/" + n + "/model")) << n << " did not run";
  }
  for (const std::string& n : kPortable) {
    EXPECT_NE(r.out.find(n + ": checked against the devices the specification allows: portable"),
              std::string::npos)
        << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/" + n + "/model")) << n << " ran";
  }
  EXPECT_NE(summary.find("CaseError: not-portable: "), std::string::npos) << summary;
  expectEachDeclarationToChange(summary);
}

TEST(CheckCase, NoCheckCaseRunsTheMistakesUnchecked) {
  const std::string dir = cli::fresh("check/unchecked");
  const Ran r = runAll(dir, " --no-check-case");
  EXPECT_EQ(r.status, 3) << "every case ran, model only: nothing compared\n" << r.out;
  EXPECT_EQ(r.out.find("checked against"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("CaseError: not-portable"), std::string::npos) << r.out;
}

TEST(CheckCase, ALibraryCaseIsCheckedOnlyWhenAsked) {
  const std::string dir = cli::fresh("check/library");
  const std::string run = "run --no-device --threads 1 --filter ray-query/generate-at-tmin --out ";
  const Ran plain = rayspec(run + dir + "/plain", dir);
  EXPECT_EQ(plain.out.find("checked against"), std::string::npos) << plain.out;
  const Ran asked = rayspec(run + dir + "/asked --check-case", dir);
  EXPECT_NE(asked.out.find("ray-query/generate-at-tmin: checked against the devices the "
                           "specification allows: portable"),
            std::string::npos)
      << asked.out;
  const Ran both = rayspec(run + dir + "/both --check-case --no-check-case", dir);
  EXPECT_EQ(both.status, 2) << both.out;
}

}  // namespace
