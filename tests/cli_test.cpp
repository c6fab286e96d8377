// The rayspec command line run as a program, as a person or CI would.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;

TEST(Isolation, CrashIsACrashAndTheNextCaseStillRuns) {
  const std::string out = fresh("crash");
  const int rc = sh(std::string(RAYSPEC_BIN) +
                        " run --no-validation --plant-fault crash --plant-fault-in 'results/*'" +
                        caseArg("results/miss-xor-closest-hit") +
                        caseArg("anyhit/ignore-odd-primitives") + " --out " + out,
                    out + "/log.txt");
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  const auto status = readDeqpCsv(out + "/results.csv");
  EXPECT_EQ(status.at("results/miss-xor-closest-hit"), "Crash") << slurp(out + "/log.txt");
  EXPECT_EQ(status.at("anyhit/ignore-odd-primitives"), "Pass") << slurp(out + "/log.txt");
  // Nothing already measured is lost: the crashed case's model bundle, the next case's both.
  EXPECT_TRUE(fs::exists(out + "/results/miss-xor-closest-hit/model/results.json"));
  EXPECT_TRUE(fs::exists(out + "/anyhit/ignore-odd-primitives/device/results.json"));
  const auto summary = nlohmann::json::parse(slurp(out + "/summary.json"));
  EXPECT_NE(summary["cases"][0]["headline"].get<std::string>().find("signal 11"), std::string::npos)
      << summary["cases"][0]["headline"];
}

TEST(Isolation, HangIsATimeout) {
  const std::string out = fresh("hang");
  const auto start = std::chrono::steady_clock::now();
  const int rc =
      sh(std::string(RAYSPEC_BIN) + " run --no-validation --plant-fault hang --timeout 3" +
             caseArg("results/miss-xor-closest-hit") + " --out " + out,
         out + "/log.txt");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  EXPECT_EQ(readDeqpCsv(out + "/results.csv").at("results/miss-xor-closest-hit"), "Timeout");
  EXPECT_LT(seconds, 60.0);
}

// Cases two at once in long-lived workers: a crash, a hang and a lost device
// planted in one case in the middle cost only that case; every other case,
// those its worker runs next included, passes.
TEST(Isolation, FaultsInAParallelRunCostOnlyTheirCase) {
  const std::vector<std::string> cases{
      "results/miss-xor-closest-hit", "anyhit/ignore-odd-primitives",
      "anyhit/ignore-keeps-tmax",     "anyhit/terminate-accepts",
      "anyhit/unused-any-hit",        "builtins/any-hit-and-intersection"};
  std::string args;
  for (const std::string& c : cases) args += caseArg(c);
  for (const auto& [fault, status] : std::vector<std::pair<std::string, std::string>>{
           {"crash", "Crash"}, {"hang", "Timeout"}, {"device-lost", "Crash"}}) {
    SCOPED_TRACE(fault);
    const std::string out = fresh("parallel-" + fault);
    const int rc = sh(std::string(RAYSPEC_BIN) + " run -j 2 --timeout 5 --plant-fault " + fault +
                          " --plant-fault-in anyhit/ignore-keeps-tmax" + args + " --out " + out +
                          " --cache-dir " + out +
                          "/cache",  // no timings: dealt in this order, the fault third
                      out + "/log.txt");
    EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
    const auto results = readDeqpCsv(out + "/results.csv");
    ASSERT_EQ(results.size(), cases.size()) << slurp(out + "/log.txt");
    for (const std::string& c : cases)
      EXPECT_EQ(results.at(c), c == "anyhit/ignore-keeps-tmax" ? status : "Pass")
          << c << "\n"
          << slurp(out + "/log.txt");
  }
}

// A driver that leaves state behind which some cases trip over (lavapipe
// 26.2.6, references/driver-reports/lavapipe-inactive-before-active.md):
// crash-if-reused kills a worker that ran one of the planted cases before.
// The crashed case runs again alone and is judged by that run, the crash a
// finding of its own (QualityWarning, "crashes only in a reused process");
// with --process-per-case-for the cases never share a worker.
TEST(Isolation, ProcessPerCaseForTheCasesThatNeedIt) {
  const std::string cases = caseArg("anyhit/ignore-odd-primitives") +
                            caseArg("anyhit/ignore-keeps-tmax") +
                            caseArg("results/miss-xor-closest-hit");
  const auto run_with = [&](const std::string& name, const std::string& extra) {
    const std::string out = fresh(name);
    const int rc = sh(std::string(RAYSPEC_BIN) +
                          " run -j 1 --no-validation --plant-fault crash-if-reused "
                          "--plant-fault-in 'anyhit/*'" +
                          cases + extra + " --out " + out,
                      out + "/log.txt");
    return std::make_pair(rc, out);
  };
  const auto [shared_rc, shared] = run_with("reused-workers", "");
  EXPECT_EQ(shared_rc, 0) << slurp(shared + "/log.txt");
  const auto crashed = readDeqpCsv(shared + "/results.csv");
  EXPECT_EQ(crashed.at("anyhit/ignore-odd-primitives"), "Pass") << slurp(shared + "/log.txt");
  EXPECT_EQ(crashed.at("anyhit/ignore-keeps-tmax"), "Warn") << slurp(shared + "/log.txt");
  EXPECT_NE(slurp(shared + "/log.txt").find("crashed in a reused worker: running it alone"),
            std::string::npos);
  EXPECT_NE(slurp(shared + "/summary.txt").find("crashes only in a reused process"),
            std::string::npos)
      << slurp(shared + "/log.txt");

  const auto [own_rc, own] = run_with("reused-own-process", " --process-per-case-for 'anyhit/*'");
  EXPECT_EQ(own_rc, 0) << slurp(own + "/log.txt");
  for (const auto& [name, status] : readDeqpCsv(own + "/results.csv"))
    EXPECT_EQ(status, "Pass") << name << "\n" << slurp(own + "/log.txt");
  EXPECT_NE(slurp(own + "/log.txt").find("a process of its own for the cases"), std::string::npos);
}

TEST(Isolation, ProcessFaultNeedsIsolation) {
  const std::string out = fresh("no-isolation");
  EXPECT_EQ(sh(std::string(RAYSPEC_BIN) + " run --no-isolation --plant-fault crash" +
                   caseArg("results/miss-xor-closest-hit") + " --out " + out,
               out + "/log.txt"),
            2);
}

TEST(Isolation, LiveProgressLineOnlyOnATerminal) {
  const std::string out = fresh("progress");
  const std::string run = std::string(RAYSPEC_BIN) + " run --no-validation" +
                          caseArg("results/miss-xor-closest-hit") + " --out " + out;
  ASSERT_EQ(sh(run, out + "/pipe.txt"), 0);
  EXPECT_EQ(slurp(out + "/pipe.txt").find("running"), std::string::npos)
      << "no live line into a pipe";
  // util-linux script(1) gives the run a pseudo-terminal.
  ASSERT_EQ(sh("script -qec \"" + run + "\" /dev/null", out + "/tty.txt"), 0)
      << slurp(out + "/tty.txt");
  EXPECT_NE(slurp(out + "/tty.txt").find("[1/1] running results/miss-xor-closest-hit..."),
            std::string::npos)
      << slurp(out + "/tty.txt");
}

TEST(Compare, SavedRunsAndBundles) {
  const std::string run = fresh("compare-run"), faulty = fresh("compare-faulty");
  ASSERT_EQ(sh(std::string(RAYSPEC_BIN) + " run --no-validation" +
                   caseArg("anyhit/ignore-odd-primitives") +
                   caseArg("results/miss-xor-closest-hit") + " --out " + run,
               run + "/log.txt"),
            0)
      << slurp(run + "/log.txt");
  ASSERT_EQ(sh(std::string(RAYSPEC_BIN) + " run --no-validation --plant-fault shift-t" +
                   caseArg("anyhit/ignore-odd-primitives") +
                   caseArg("results/miss-xor-closest-hit") + " --out " + faulty,
               faulty + "/log.txt"),
            1)
      << slurp(faulty + "/log.txt");

  // A run folder against itself: every case's device against the same device.
  const std::string same = fresh("compare-same");
  EXPECT_EQ(sh(std::string(RAYSPEC_BIN) + " compare " + run + " " + run + " --out " + same,
               same + "/log.txt"),
            0)
      << slurp(same + "/log.txt");
  auto status = readDeqpCsv(same + "/results.csv");
  EXPECT_EQ(status.size(), 2u);
  EXPECT_EQ(status["anyhit/ignore-odd-primitives"], "Pass");

  // Today's faulty driver against yesterday's good one, cases matched by name.
  const std::string drivers = fresh("compare-drivers");
  EXPECT_EQ(sh(std::string(RAYSPEC_BIN) + " compare " + faulty + " " + run + " --out " + drivers,
               drivers + "/log.txt"),
            1);
  status = readDeqpCsv(drivers + "/results.csv");
  EXPECT_EQ(status["anyhit/ignore-odd-primitives"], "Fail") << slurp(drivers + "/log.txt");
  EXPECT_NE(slurp(drivers + "/summary.txt").find("R-PREC"), std::string::npos);

  // One bundle against another: the saved faulty device against its model.
  const std::string bundles = fresh("compare-bundles");
  const std::string c = "/anyhit/ignore-odd-primitives";
  EXPECT_EQ(sh(std::string(RAYSPEC_BIN) + " compare " + faulty + c + "/device " + faulty + c +
                   "/model --out " + bundles,
               bundles + "/log.txt"),
            1);
  EXPECT_EQ(readDeqpCsv(bundles + "/results.csv")["anyhit/ignore-odd-primitives"], "Fail")
      << slurp(bundles + "/log.txt");
}

// A run with a planted failure, whose reports the tests below read.
class ReportRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = fresh("report");
    rc_ = sh(std::string(RAYSPEC_BIN) +
                 " run --plant-fault swap-primitive-id --plant-fault-in 'anyhit/*'" +
                 caseArg("anyhit/ignore-odd-primitives") + caseArg("results/miss-xor-closest-hit") +
                 caseArg("watertight/shared-edges") + " --out " + out_,
             out_ + "/log.txt");
  }
  static std::string out_;
  static int rc_;
};
std::string ReportRun::out_;
int ReportRun::rc_ = -1;

// The DOM headless Chromium has once report.html (and its script) loaded at
// the address's fragment, which may set the page's filter ("" on failure,
// the reason in a test failure).
std::string reportDom(const std::string& out, const std::string& fragment,
                      const std::string& name) {
  const std::string profile = fresh("chromium-profile-" + name);
  const std::string dom = out + "/dom-" + name + ".html";
  const int rc =
      sh("chromium --headless --no-sandbox --disable-gpu --disable-background-networking "
         "--disable-component-update --disable-sync --no-first-run --allow-file-access-from-files "
         "--virtual-time-budget=5000 --user-data-dir=" +
             profile + " --dump-dom 'file://" + out + "/report.html" + fragment + "' > " + dom +
             " 2> " + out + "/chromium-stderr.txt; cat " + dom,
         out + "/chromium-log.txt");
  EXPECT_EQ(rc, 0) << slurp(out + "/chromium-stderr.txt");
  return rc == 0 ? slurp(dom) : std::string();
}

std::string bodyTag(const std::string& dom) {
  std::smatch m;
  return std::regex_search(dom, m, std::regex(R"(<body[^>]*>)")) ? m.str() : std::string();
}

// Whether the filter hid the element of a case: its opening tag as the DOM has it.
bool caseHidden(const std::string& dom, const std::string& name) {
  const size_t id = dom.find("id=\"" + name + "\"");
  EXPECT_NE(id, std::string::npos) << name;
  if (id == std::string::npos) return false;
  const size_t open = dom.rfind('<', id);
  return dom.substr(open, dom.find('>', id) - open).find(" hidden") != std::string::npos;
}

TEST_F(ReportRun, ReportHtmlOpensInChromiumWithEveryImageShown) {
  ASSERT_EQ(rc_, 1) << slurp(out_ + "/log.txt");
  const std::string c = out_ + "/anyhit/ignore-odd-primitives";
  for (const char* side : {"/device/", "/model/", "/diff/"})
    ASSERT_TRUE(fs::exists(c + side + "primitive.png")) << c + side << "primitive.png";
  const std::string text = reportDom(out_, "", "plain");
  const std::string body = bodyTag(text);
  ASSERT_FALSE(body.empty()) << text.substr(0, 400);
  EXPECT_NE(body.find("data-checked=\"1\""), std::string::npos)
      << "the page's check never ran: " << body;
  EXPECT_NE(body.find("data-broken-images=\"0\""), std::string::npos) << body;
  EXPECT_NE(body.find("data-script-errors=\"0\""), std::string::npos) << body;
  EXPECT_NE(body.find("data-shown=\"3\""), std::string::npos) << "no filter: every case" << body;
  std::smatch images;
  ASSERT_TRUE(std::regex_search(body, images, std::regex(R"re(data-images="([0-9]+)")re"))) << body;
  EXPECT_GE(std::stoi(images[1]), 3) << "device, model and difference images of the failing case";
  // The failing case comes first, with its per-ray table folded.
  EXPECT_LT(text.find("anyhit/ignore-odd-primitives"), text.find("results/miss-xor-closest-hit"));
  EXPECT_NE(text.find("<th>field</th><th>device</th><th>model</th>"), std::string::npos);
}

// The filter, set from the address as a link of the summary tables sets it:
// by status, family, rule and text, the cases it leaves out hidden.
TEST_F(ReportRun, ReportHtmlFiltersByStatusFamilyRuleAndText) {
  ASSERT_EQ(rc_, 1) << slurp(out_ + "/log.txt");
  const std::string fail = "anyhit/ignore-odd-primitives", miss = "results/miss-xor-closest-hit",
                    edges = "watertight/shared-edges";
  struct Filter {
    std::string fragment, name;
    std::vector<std::string> shown;
  };
  const std::vector<Filter> filters{
      {"#filter?status=Pass", "status", {miss, edges}},
      {"#filter?family=anyhit", "family", {fail}},
      {"#filter?rule=R-MISS-XOR-CHIT", "rule", {fail, miss}},
      {"#filter?q=XOR-CLOSEST", "search", {miss}},
      {"#filter?family=watertight&status=Fail", "nothing", {}},
  };
  for (const Filter& f : filters) {
    SCOPED_TRACE(f.fragment);
    const std::string dom = reportDom(out_, f.fragment, f.name);
    const std::string body = bodyTag(dom);
    EXPECT_NE(body.find("data-script-errors=\"0\""), std::string::npos) << body;
    EXPECT_NE(body.find("data-shown=\"" + std::to_string(f.shown.size()) + "\""), std::string::npos)
        << body;
    for (const std::string& name : {fail, miss, edges})
      EXPECT_EQ(caseHidden(dom, name),
                std::find(f.shown.begin(), f.shown.end(), name) == f.shown.end())
          << name;
    EXPECT_NE(dom.find(std::to_string(f.shown.size()) + " of 3 cases shown"), std::string::npos);
  }
}

TEST_F(ReportRun, ResultsCsvReadsBackAsDeqpRunnerCsv) {
  ASSERT_EQ(rc_, 1) << slurp(out_ + "/log.txt");
  const auto status = readDeqpCsv(out_ + "/results.csv");
  ASSERT_EQ(status.size(), 3u) << slurp(out_ + "/results.csv");
  EXPECT_EQ(status.at("anyhit/ignore-odd-primitives"), "Fail");
  EXPECT_EQ(status.at("results/miss-xor-closest-hit"), "Pass");
  EXPECT_EQ(status.at("watertight/shared-edges"), "Pass");
}

}  // namespace
