// The run module: the Backend adapters, one isolation function for both
// sides (timeout, memory limit, crash), children that die with their parent,
// per-case CaseErrors, and the exit status.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "bundle/results_io.h"
#include "compare/compare_results.h"
#include "parse/parse_case.h"
#include "report/case_journal.h"
#include "report/rule_catalog.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "run/case_steps.h"
#include "run/child_process.h"
#include "run/isolation.h"
#include "run/model_adapter.h"
#include "run/run_loop.h"
#include "run/vulkan_adapter.h"
#include "suite_cases.h"
#include "temp_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

std::string tempDir(const std::string& name) {
  return freshTempDir("rayspec-run-test/" + name);
}

// A model side whose engine does something bad before answering.
class MisbehavingModel : public Backend {
 public:
  explicit MisbehavingModel(std::function<void()> act) : act_(std::move(act)) {}
  std::string name() const override { return "model"; }
  std::string description() const override { return "a model that misbehaves"; }
  Result<Results> run(const Case& c, const Plan&) override {
    act_();
    Results r;
    r.backend = name();
    r.case_name = c.name;
    return r;
  }
  std::vector<std::string> close() override { return {}; }

 private:
  std::function<void()> act_;
};

Side misbehavingSide(std::function<void()> act) {
  return Side{"model", "model", [act] { return std::make_unique<MisbehavingModel>(act); }, {}};
}

Side modelSide() {
  return Side{"model", "model", [] { return std::make_unique<ModelAdapter>(ModelOptions{}); }, {}};
}

Side deviceSide() {
  VulkanOptions v;
  v.validation = false;
  return Side{"device", "vulkan", [v] { return std::make_unique<VulkanAdapter>(v); }, {}};
}

// ---- item 1: one Backend interface, two adapters ----------------------------

TEST(Backend, ModelAndDeviceAnswerThroughOneInterface) {
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const Plan plan = derivePlan(c);
  VulkanOptions v;
  v.validation = false;
  std::unique_ptr<Backend> model = std::make_unique<ModelAdapter>(ModelOptions{});
  std::unique_ptr<Backend> device = std::make_unique<VulkanAdapter>(v);
  EXPECT_EQ(model->name(), "model");
  EXPECT_EQ(device->name(), "vulkan");
  EXPECT_NE(model->description().find("exact"), std::string::npos) << model->description();
  EXPECT_NE(device->description().find("llvmpipe"), std::string::npos) << device->description();
  const Results m = *model->run(c, plan), d = *device->run(c, plan);
  ASSERT_TRUE(m.ok()) << m.statusText();
  ASSERT_TRUE(d.ok()) << d.statusText();
  EXPECT_EQ(compareResults(c, plan, d, m).status, Status::Pass);
  EXPECT_TRUE(device->close().empty());
}

TEST(Backend, DeviceThatIsNotThereAnswersNotSupportedWithWhy) {
  VulkanOptions v;
  v.device_filter = "nosuchdevice";
  v.validation = false;
  VulkanAdapter device(v);
  EXPECT_FALSE(device.found());
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const Results r = *device.run(c, derivePlan(c));
  EXPECT_EQ(r.status, SideStatus::NotSupported);
  EXPECT_NE(r.status_detail.find("nosuchdevice"), std::string::npos) << r.status_detail;
}

// ---- item 2: both sides through one isolation function ----------------------

TEST(Isolation, BothSidesRunIsolatedAndAgree) {
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const Plan plan = derivePlan(c);
  const std::string dir = tempDir("both-sides");
  const ChildLimits limits{60, kDefaultMemoryLimit};
  const SideResult m = *runIsolated(modelSide(), c, plan, limits, dir + "/model");
  const SideResult d = *runIsolated(deviceSide(), c, plan, limits, dir + "/device");
  ASSERT_TRUE(m.results.ok()) << m.results.statusText();
  ASSERT_TRUE(d.results.ok()) << d.results.statusText();
  EXPECT_EQ(m.results.backend, "model");
  EXPECT_EQ(d.results.backend, "vulkan");
  EXPECT_EQ(compareResults(c, plan, d.results, m.results).status, Status::Pass);
  EXPECT_TRUE(fs::exists(dir + "/model/results.json"));
}

TEST(Isolation, EmbreeAndTbbStartUnderTheDefaultMemoryLimit) {
  // Every thread of the model (a case with callables, lights and a camera).
  const Case c = suiteCaseFile("callable/lights");
  const Plan plan = derivePlan(c);
  const SideResult m = *runIsolated(modelSide(), c, plan, ChildLimits{120, kDefaultMemoryLimit},
                                    tempDir("big-model"));
  EXPECT_TRUE(m.results.ok()) << m.results.statusText();
  EXPECT_EQ(m.results.records.size(), size_t(c.rays.width) * c.rays.height * recordWords());
}

TEST(Isolation, ModelHangIsATimeout) {
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const auto start = std::chrono::steady_clock::now();
  const SideResult m = *runIsolated(misbehavingSide([] {
                                      for (;;) pause();
                                    }),
                                    c, derivePlan(c), ChildLimits{1, 0}, tempDir("hang"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_EQ(m.results.status, SideStatus::Timeout);
  EXPECT_EQ(m.results.backend, "model");
  EXPECT_EQ(m.results.status_detail, "the model process ran longer than 1 s (killed)");
  EXPECT_EQ(backendVerdict(m.results).headline().rfind("Timeout: model: ", 0), 0u)
      << backendVerdict(m.results).headline();
}

TEST(Isolation, ModelCrashIsACrash) {
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const std::string dir = tempDir("crash");
  // SIG_DFL: the signal itself, not AddressSanitizer's report of it (asan preset).
  const SideResult m = *runIsolated(misbehavingSide([] {
                                      std::signal(SIGSEGV, SIG_DFL);
                                      std::raise(SIGSEGV);
                                    }),
                                    c, derivePlan(c), ChildLimits{30, 0}, dir);
  EXPECT_EQ(m.results.status, SideStatus::Crash);
  EXPECT_NE(m.results.status_detail.find("the model process died of signal 11"), std::string::npos)
      << m.results.status_detail;
  // The dead side's bundle says so (a saved run judged elsewhere shows the crash).
  std::string error;
  const Results saved = orError(readResults(dir), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(saved.status, SideStatus::Crash);
  EXPECT_EQ(saved.case_hash, c.source_hash);
}

TEST(IsolationMemoryLimit, ModelBeyondTheMemoryLimitIsACrash) {
  if (!memoryLimitApplies())
    GTEST_SKIP() << "AddressSanitizer build: no memory limit is set on children";
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  // Without a limit it holds 1 GiB and answers; under 256 MiB it cannot.
  auto hog = [] {
    std::vector<std::unique_ptr<char[]>> blocks;
    for (int i = 0; i < 16; ++i) {
      blocks.push_back(std::make_unique<char[]>(64 << 20));
      std::fill_n(blocks.back().get(), 64 << 20, char(i));
    }
  };
  const SideResult m = *runIsolated(misbehavingSide(hog), c, derivePlan(c),
                                    ChildLimits{60, 256u << 20}, tempDir("memory"));
  EXPECT_EQ(m.results.status, SideStatus::Crash);
  EXPECT_EQ(m.results.status_detail,
            "the model process ran out of memory (--memory-limit 256 MiB)");
}

TEST(Isolation, BundleThatCannotBeWrittenIsAHarnessErrorNotACrash) {
  const Case c = suiteCaseFile("results/miss-xor-closest-hit");
  const std::string dir = tempDir("unwritable");
  std::ofstream(dir + "/file") << "a file where the bundle's folder should go";
  const Result<SideResult> m =
      runIsolated(modelSide(), c, derivePlan(c), ChildLimits{60, 0}, dir + "/file/model");
  ASSERT_FALSE(m) << "a bundle that cannot be written was read back";
  EXPECT_EQ(m.error().kind, ErrorKind::Harness);
  EXPECT_EQ(m.error().message.rfind("model side: ", 0), 0u) << m.error().message;
}

// ---- item 3: a child dies with its parent ------------------------------------

bool processGone(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), {});
  const size_t paren = stat.rfind(')');
  return paren == std::string::npos || stat[paren + 2] == 'Z' || stat[paren + 2] == 'X';
}

// Under AddressSanitizer a child checks for leaks before it exits (an
// ordinary exit would skip LeakSanitizer): a leak ends it with kChildLeaked.
TEST(ChildLeaks, ALeakIsFoundUnderAddressSanitizer) {
  if (!kAddressSanitizer) GTEST_SKIP() << "only the asan preset checks children for leaks";
  const ChildEnd clean = runChild([](std::string&) { return 0; }, ChildLimits{});
  EXPECT_EQ(clean.code, 0);
  const ChildEnd leaky = runChild(
      [](std::string&) {
        int* lost = new int[1000];
        lost[0] = 1;
        lost = nullptr;
        return 0;
      },
      ChildLimits{});
  EXPECT_EQ(leaky.how, ChildEnd::How::Exited);
  EXPECT_EQ(leaky.code, kChildLeaked);
  EXPECT_NE(describeChildEnd(leaky, "the model process", ChildLimits{}).find("leaked memory"),
            std::string::npos);
}

TEST(ChildProcess, DiesWithItsParent) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t parent = fork();
  if (parent == 0) {
    // A parent whose child hangs; the child tells the test its pid.
    runChild(
        [&](std::string&) {
          const pid_t me = getpid();
          [[maybe_unused]] ssize_t n = write(fds[1], &me, sizeof me);
          for (;;) pause();
          return 0;
        },
        ChildLimits{});
    _exit(0);
  }
  close(fds[1]);
  pid_t child = 0;
  ASSERT_EQ(read(fds[0], &child, sizeof child), static_cast<ssize_t>(sizeof child));
  close(fds[0]);
  kill(parent, SIGKILL);
  waitpid(parent, nullptr, 0);
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    gone = processGone(child);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (!gone) kill(child, SIGKILL);
  EXPECT_TRUE(gone) << "the hung child outlived its killed parent";
}

// ---- items 4 and 5: the case or the harness is at fault ----------------------

TEST(CaseSteps, ExceptionWhileJudgingIsACaseError) {
  const CaseOutcome o = guardCase("fam/long-image", {"R-IGNORE"}, []() -> CaseOutcome {
    throw fs::filesystem_error("status", fs::path(std::string(300, 'i')),
                               std::make_error_code(std::errc::filename_too_long));
  });
  EXPECT_EQ(o.status, Status::CaseError);
  EXPECT_EQ(o.name, "fam/long-image");
  EXPECT_EQ(o.rules, std::vector<std::string>{"R-IGNORE"});
  EXPECT_NE(o.headline.find("File name too long"), std::string::npos) << o.headline;
  EXPECT_TRUE(isFailing(o.status));
}

TEST(CaseSteps, ErrorOfAStepIsACaseError) {
  const CaseOutcome o = guardCase("fam/unreadable", {"R-IGNORE"}, []() -> Result<CaseOutcome> {
    return errorOf(ErrorKind::Harness, "model side: no results.json in out/fam/unreadable/model");
  });
  EXPECT_EQ(o.status, Status::CaseError);
  EXPECT_EQ(o.headline,
            "CaseError: harness: the harness failed on this case: model side: no results.json "
            "in out/fam/unreadable/model");
}

TEST(CaseSteps, DetailsTheReportsCannotHoldAreACaseErrorAndTheReportsAreStillWritten) {
  const std::string dir = tempDir("report-seam");
  // The report writer, with a seam: an image name the file system refuses is
  // a case's detail the reports cannot hold (ErrorKind::Input).
  const ReportWriter writer = [](const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                                 const std::string& out) -> Result<void> {
    for (const CaseOutcome& o : outcomes)
      for (const std::string& im : o.images)
        if (im.size() > 255)
          return errorOf(ErrorKind::Input, out + "/" + o.name + "/device/" + im.substr(0, 8) +
                                               "...png: File name too long");
    return writeReports(outcomes, info, out);
  };
  CaseOutcome long_image;
  long_image.name = "fam/long-image";
  long_image.images = {std::string(300, 'i')};
  CaseOutcome next;
  next.name = "fam/next";
  RunInfo info;
  info.planned_cases = 2;
  std::vector<CaseOutcome> outcomes{long_image, next};
  EXPECT_EQ(errorText(writeRunReports(outcomes, Baseline{}, info, dir, writer)), "");
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_EQ(outcomes[0].status, Status::CaseError);
  EXPECT_NE(outcomes[0].headline.find("the reports could not show this case: "), std::string::npos)
      << outcomes[0].headline;
  EXPECT_NE(outcomes[0].headline.find("File name too long"), std::string::npos);
  EXPECT_EQ(outcomes[1].status, Status::Pass);
  EXPECT_FALSE(fs::exists(dir + "/.report-check")) << "the scratch folder is left behind";
  std::ifstream csv(dir + "/results.csv");
  std::string first, second;
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_EQ(first.rfind("fam/long-image,Fail,", 0), 0u) << first;
  EXPECT_EQ(second.rfind("fam/next,Pass,", 0), 0u) << second;
}

// nlohmann-json cannot write text that is not UTF-8: the real writers turn
// its exception into an Input error, and the case whose message holds such
// text becomes the CaseError, while the others keep their verdicts.
TEST(CaseSteps, TextThatIsNotUtf8IsACaseErrorOfThatCaseAlone) {
  const std::string dir = tempDir("report-utf8");
  CaseOutcome broken;
  broken.name = "fam/broken";
  broken.verdict.add({Status::Fail, "R-MISS", "bad byte \xff here", {}, 0});
  broken.deriveFromVerdict();
  CaseOutcome fine;
  fine.name = "fam/fine";
  fine.verdict.add({Status::Pass, "R-MISS", "fine", {}, 0});
  fine.deriveFromVerdict();
  RunInfo info;
  std::vector<CaseOutcome> outcomes{broken, fine};
  ASSERT_EQ(errorText(writeRunReports(outcomes, Baseline{}, info, dir)), "");
  EXPECT_EQ(outcomes[0].status, Status::CaseError);
  EXPECT_NE(outcomes[0].headline.find("the reports could not show this case: "), std::string::npos)
      << outcomes[0].headline;
  EXPECT_NE(outcomes[0].headline.find("UTF-8"), std::string::npos) << outcomes[0].headline;
  EXPECT_EQ(outcomes[1].status, Status::Pass);
  std::ifstream summary(dir + "/summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_EQ(j.at("case_errors"), nlohmann::json::array({"fam/broken"}));
}

// A report that cannot be written at all is the run's error, not any case's:
// no case is looked at alone and every verdict stays.
TEST(CaseSteps, ReportsThatCannotBeWrittenLeaveTheCasesAsTheyWere) {
  int calls = 0;
  const ReportWriter writer = [&calls](const std::vector<CaseOutcome>&, const RunInfo&,
                                       const std::string& out) -> Result<void> {
    ++calls;
    return errorOf(ErrorKind::Harness, "cannot write " + out + "/results.csv");
  };
  CaseOutcome one;
  one.name = "fam/one";
  std::vector<CaseOutcome> outcomes{one};
  const Result<void> written =
      writeRunReports(outcomes, Baseline{}, RunInfo{}, tempDir("report-io"), writer);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().kind, ErrorKind::Harness);
  EXPECT_NE(written.error().message.find("results.csv"), std::string::npos);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(outcomes[0].status, Status::Pass);
}

// The journal refuses such a case the same way: it joins as a CaseError.
TEST(CaseSteps, JournalTakesACaseItCannotShowAsACaseError) {
  const std::string dir = tempDir("journal-utf8");
  CaseOutcome o;
  o.name = "fam/broken";
  o.verdict.add({Status::Pass, "R-MISS", "\xc3(", {}, 0});
  o.deriveFromVerdict();
  journalCase(o, Baseline{}, dir);
  EXPECT_EQ(o.status, Status::CaseError);
  EXPECT_NE(o.headline.find("the reports could not show this case"), std::string::npos);
  const auto journal = readJournal(dir);
  ASSERT_TRUE(journal) << journal.error().format();
  ASSERT_TRUE(*journal);
  ASSERT_EQ((*journal)->size(), 1u);
  EXPECT_EQ((*journal)->at(0).status, Status::CaseError);
}

TEST(CaseSteps, CaseFileThatDoesNotParseIsACaseError) {
  const std::string dir = tempDir("case-file");
  const std::string path = dir + "/bad.yaml";
  std::ofstream(path) << "rules: [R-IGNORE]\nscene: 12\n";
  const std::optional<CaseOutcome> o = caseFileError({path, "fam/bad"}, parseCaseFile(path, dir));
  ASSERT_TRUE(o);
  EXPECT_EQ(o->status, Status::CaseError);
  EXPECT_EQ(o->verdict.findings.at(0).rule, "case-file");
  EXPECT_NE(o->headline.find(path + ":"), std::string::npos) << o->headline;
}

TEST(CaseSteps, UnknownRuleLabelIsACaseError) {
  const auto catalog = loadRuleCatalog(RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml");
  ASSERT_TRUE(catalog) << catalog.error().format();
  const std::vector<std::string> labels = ruleLabels(*catalog);
  const std::string path = kSuiteCases + "/results/miss-xor-closest-hit.yaml";
  EXPECT_FALSE(caseFileError({path, "results/miss-xor-closest-hit"},
                             parseCaseFile(path, kSuiteCases, &labels)))
      << "a good case is no error";
  const std::string dir = tempDir("rule-label");
  const std::string bad = dir + "/unknown-rule.yaml";
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("rules: [");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 8, "R-NO-SUCH-RULE, ");
  std::ofstream(bad) << text;
  const std::optional<CaseOutcome> o =
      caseFileError({bad, "fam/unknown-rule"}, parseCaseFile(bad, dir, &labels));
  ASSERT_TRUE(o);
  EXPECT_EQ(o->status, Status::CaseError);
  EXPECT_NE(o->headline.find("R-NO-SUCH-RULE"), std::string::npos) << o->headline;
  EXPECT_NE(o->headline.find(bad + ":"), std::string::npos)
      << "the label's line:col: " << o->headline;
}

// ---- item 6: exit statuses --------------------------------------------------

RunSummary summaryOf(std::vector<Status> statuses) {
  RunSummary s(statuses.size());
  for (Status st : statuses) {
    CaseOutcome o;
    o.name = "fam/case";
    o.status = st;
    s.add(o);
  }
  return s;
}

TEST(ExitStatus, NothingComparedIsNotASuccess) {
  EXPECT_EQ(runExitStatus(summaryOf({Status::Pass, Status::NotSupported}), 2, true, 0), kExitPass);
  EXPECT_EQ(runExitStatus(summaryOf({Status::Pass, Status::Fail}), 2, true, 0), kExitFailing);
  EXPECT_EQ(runExitStatus(summaryOf({Status::CaseError}), 1, true, 0), kExitFailing);
  // A single NotSupported case is ctest's skip only when a device was there to say so.
  EXPECT_EQ(runExitStatus(summaryOf({Status::NotSupported}), 1, true, 0), kExitNotSupported);
  EXPECT_EQ(runExitStatus(summaryOf({Status::NotSupported}), 1, false, 0), kExitNothingCompared);
  EXPECT_EQ(runExitStatus(summaryOf({Status::NotSupported, Status::NotSupported}), 2, true, 0),
            kExitNothingCompared);
  EXPECT_EQ(runExitStatus(summaryOf({}), 3, true, 0), kExitNothingCompared);
  EXPECT_EQ(runExitStatus(summaryOf({Status::Pass}), 2, true, SIGTERM), 128 + SIGTERM);
}

}  // namespace
}  // namespace rayspec
