// `rayspec show` run as a program: a missing case file, rule labels outside
// the catalog, the undefined behaviour of a robustness probe.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {
namespace fs = std::filesystem;

struct ShowRun {
  int status = -1;
  std::string out, err;
};

// Runs `rayspec show ARGS` from the source folder; stdout and stderr apart.
ShowRun show(const std::string& args) {
  const std::string dir = std::string(RAYSPEC_TEST_OUT) + "/show";
  fs::create_directories(dir);
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  const std::string command =
      "cd " RAYSPEC_SOURCE_DIR " && " RAYSPEC_BIN " show " + args + " > " + out + " 2> " + err;
  const int s = std::system(command.c_str());
  ShowRun r;
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  std::ifstream o(out), e(err);
  std::stringstream so, se;
  so << o.rdbuf();
  se << e.rdbuf();
  r.out = so.str();
  r.err = se.str();
  return r;
}

TEST(Show, AMissingCaseFileIsAClearErrorAndANonZeroExit) {
  for (const std::string& arg : {std::string("cases/nope.yaml"), std::string("nope/x")}) {
    const ShowRun r = show(arg);
    EXPECT_NE(r.status, 0) << arg;
    EXPECT_NE(r.err.find("no such case file: '" + arg + "'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".yaml.yaml"), std::string::npos) << "no mangled path: " << r.err;
    EXPECT_EQ(r.out, "") << arg;
  }
  const ShowRun ok = show("builtins/closest-hit-and-miss --no-glsl");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("Case builtins/closest-hit-and-miss"), std::string::npos);
}

TEST(Show, AnUnknownRuleLabelIsAnErrorAtItsLineAndColumn) {
  const std::string path = std::string(RAYSPEC_TEST_OUT) + "/show/unknown-rule.yaml";
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << "rules: [R-MASK, R-NOT-A-RULE]\n"
                         "rays: {list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]}\n"
                         "pipeline: {miss: [[]]}\n";
  const ShowRun r = show(path + " --no-glsl");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(path + ":1:17: rules[1]: unknown rule label 'R-NOT-A-RULE'"), std::string::npos) << r.err;
}

TEST(Show, ARobustnessProbeListsItsUndefinedBehaviour) {
  const ShowRun r = show("robustness/undefined-rays --no-glsl");
  EXPECT_EQ(r.status, 0) << r.err;
  const size_t at = r.out.find("Undefined behaviour (R-UB probe");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rays.list[4].tmin: tmin is NaN", at), std::string::npos) << r.out;
}

}  // namespace
