// The run loop as a program: model isolation, children that die with their
// parent, interrupted runs, case errors, exit statuses, long ray lists, device
// errors.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::kBin;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

nlohmann::json summaryOf(const std::string& out) {
  return nlohmann::json::parse(slurp(out + "/summary.json"));
}

// The status and headline of one case in summary.json.
std::pair<std::string, std::string> caseIn(const nlohmann::json& summary, const std::string& name) {
  for (const auto& c : summary["cases"])
    if (c["name"] == name) return {c["status"], c["headline"]};
  return {"(absent)", ""};
}

// Writes a case file built from text into dir; returns its path.
std::string writeCase(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

// A case file of the suite with one line replaced.
std::string editedCase(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = slurp(cli::kCases + name + ".yaml");
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// ---- processes -------------------------------------------------------------

// Starts a shell command in the background (exec'd: the pid is the program's).
pid_t spawn(const std::string& command, const std::string& log) {
  const std::string line =
      "unset GTEST_TOTAL_SHARDS GTEST_SHARD_INDEX GTEST_SHARD_STATUS_FILE; exec " + command +
      " > " + log + " 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// State letter and parent of a process from /proc/PID/stat ('\0' when gone).
std::pair<char, pid_t> procState(pid_t pid) {
  const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  const size_t paren = stat.rfind(')');
  if (paren == std::string::npos) return {'\0', 0};
  std::istringstream rest(stat.substr(paren + 1));
  char state = '\0';
  pid_t ppid = 0;
  rest >> state >> ppid;
  return {state, ppid};
}

bool gone(pid_t pid) {
  const char state = procState(pid).first;
  return state == '\0' || state == 'Z' || state == 'X';
}

std::set<pid_t> childrenOf(pid_t parent) {
  std::set<pid_t> out;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = std::stoi(name);
    const auto [state, ppid] = procState(pid);
    if (ppid == parent && state != 'Z') out.insert(pid);
  }
  return out;
}

template <class F>
bool waitUntil(F done, double seconds) {
  const auto start = Clock::now();
  while (since(start) < seconds) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

// A run of two cases whose second case's device child hangs (planted fault
// `hang`, no timeout to speak of). Returns once the first case is reported
// and the hung child is the only child left; *children holds it.
pid_t startHungRun(const std::string& out, std::set<pid_t>* children) {
  const pid_t parent = spawn(
      kBin + " run --no-validation --plant-fault hang --plant-fault-in 'anyhit/*' --timeout 300" +
          caseArg("results/miss-xor-closest-hit") + caseArg("anyhit/ignore-odd-primitives") +
          " --out " + out,
      out + "/log.txt");
  const bool model_done = waitUntil(
      [&] { return fs::exists(out + "/anyhit/ignore-odd-primitives/model/results.json"); }, 60);
  EXPECT_TRUE(model_done) << slurp(out + "/log.txt");
  // Stable for a second: the device child, hung (not the model child on its way out).
  waitUntil(
      [&] {
        const std::set<pid_t> before = childrenOf(parent);
        std::this_thread::sleep_for(std::chrono::seconds(1));
        *children = childrenOf(parent);
        return !children->empty() && *children == before;
      },
      30);
  EXPECT_FALSE(children->empty()) << "no hung child to watch";
  return parent;
}

void killLeftovers(const std::set<pid_t>& pids) {
  for (pid_t p : pids)
    if (!gone(p)) kill(p, SIGKILL);
}

// ---- item 3 and 8: kill -9 of the parent -----------------------------------

class KilledRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = fresh("killed-run");
    parent_ = startHungRun(out_, &children_);
    kill(parent_, SIGKILL);
    int status = 0;
    waitpid(parent_, &status, 0);
    killed_by_ = WIFSIGNALED(status) ? WTERMSIG(status) : -1;
    all_gone_ = waitUntil(
        [] {
          for (pid_t p : children_)
            if (!gone(p)) return false;
          return true;
        },
        5);
    killLeftovers(children_);
  }
  static std::string out_;
  static pid_t parent_;
  static std::set<pid_t> children_;
  static int killed_by_;
  static bool all_gone_;
};
std::string KilledRun::out_;
pid_t KilledRun::parent_ = 0;
std::set<pid_t> KilledRun::children_;
int KilledRun::killed_by_ = 0;
bool KilledRun::all_gone_ = false;

TEST_F(KilledRun, HungChildDiesWithItsParent) {
  ASSERT_EQ(killed_by_, SIGKILL);
  ASSERT_FALSE(children_.empty());
  EXPECT_TRUE(all_gone_) << "a child of the killed run is still running " << children_.size();
}

TEST_F(KilledRun, ReportsStayMarkedInterrupted) {
  const nlohmann::json summary = summaryOf(out_);
  EXPECT_TRUE(summary["interrupted"].get<bool>());
  EXPECT_EQ(summary["planned_cases"], 2);
  EXPECT_EQ(summary["cases"].size(), 1u);
  EXPECT_EQ(slurp(out_ + "/summary.txt").rfind("INTERRUPTED: 1 of 2 planned cases ran\n", 0), 0u)
      << slurp(out_ + "/summary.txt");
  EXPECT_NE(slurp(out_ + "/report.html").find("INTERRUPTED: 1 of 2 planned cases ran"),
            std::string::npos);
}

// The killed run finished by --resume: the case it had is kept as it was
// (its bundle untouched), the rest run, and the reports are complete.
TEST_F(KilledRun, ResumeFinishesItAndKeepsWhatRan) {
  const std::string kept = out_ + "/results/miss-xor-closest-hit/device/results.json";
  ASSERT_TRUE(fs::exists(kept));
  const auto written = fs::last_write_time(kept);
  const std::string run = kBin + " run --no-validation --resume" +
                          caseArg("results/miss-xor-closest-hit") +
                          caseArg("anyhit/ignore-odd-primitives") + " --out " + out_;
  ASSERT_EQ(sh(run, out_ + "/resume.txt"), 0) << slurp(out_ + "/resume.txt");
  EXPECT_NE(slurp(out_ + "/resume.txt").find("1 cases already ran"), std::string::npos)
      << slurp(out_ + "/resume.txt");
  EXPECT_EQ(fs::last_write_time(kept), written) << "the case that ran before ran again";
  const nlohmann::json summary = summaryOf(out_);
  EXPECT_FALSE(summary["interrupted"].get<bool>());
  ASSERT_EQ(summary["cases"].size(), 2u);
  EXPECT_EQ(summary["cases"][1]["status"], "Pass");
  EXPECT_EQ(slurp(out_ + "/summary.txt").rfind("complete: 2 of 2 cases\n", 0), 0u)
      << slurp(out_ + "/summary.txt");
  // Resuming into a folder from another kind of run is refused.
  EXPECT_EQ(sh(run + " --model fast", out_ + "/resume-fast.txt"), 2);
  EXPECT_NE(slurp(out_ + "/resume-fast.txt").find("model tier"), std::string::npos)
      << slurp(out_ + "/resume-fast.txt");
}

// ---- item 8: SIGINT / SIGTERM ----------------------------------------------

TEST(Interrupt, SignalFinishesTheReportsAndExitsNonZero) {
  for (int sig : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(strsignal(sig));
    const std::string out = fresh(std::string("interrupt-") + std::to_string(sig));
    std::set<pid_t> children;
    const pid_t parent = startHungRun(out, &children);
    const auto start = Clock::now();
    kill(parent, sig);
    int status = 0;
    waitpid(parent, &status, 0);
    EXPECT_LT(since(start), 10.0);
    ASSERT_TRUE(WIFEXITED(status)) << slurp(out + "/log.txt");
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << slurp(out + "/log.txt");
    EXPECT_TRUE(waitUntil(
        [&] {
          for (pid_t p : children)
            if (!gone(p)) return false;
          return true;
        },
        5));
    killLeftovers(children);
    const nlohmann::json summary = summaryOf(out);
    EXPECT_TRUE(summary["interrupted"].get<bool>());
    EXPECT_EQ(summary["planned_cases"], 2);
    EXPECT_EQ(caseIn(summary, "results/miss-xor-closest-hit").first, "Pass");
    EXPECT_EQ(caseIn(summary, "anyhit/ignore-odd-primitives").first, "(absent)")
        << "nothing measured, nothing said";
    EXPECT_EQ(readDeqpCsv(out + "/results.csv").size(), 1u);
    EXPECT_NE(slurp(out + "/log.txt").find("INTERRUPTED: 1 of 2 cases ran"), std::string::npos);
  }
}

TEST(Interrupt, CompleteRunIsNotMarked) {
  const std::string out = fresh("complete-run");
  ASSERT_EQ(
      sh(kBin + " run --no-validation" + caseArg("results/miss-xor-closest-hit") + " --out " + out,
         out + "/log.txt"),
      0)
      << slurp(out + "/log.txt");
  const nlohmann::json summary = summaryOf(out);
  EXPECT_FALSE(summary["interrupted"].get<bool>());
  EXPECT_EQ(summary["planned_cases"], 1);
  EXPECT_EQ(slurp(out + "/summary.txt").rfind("complete: 1 of 1 cases\n", 0), 0u);
}

// ---- item 2: the model isolated like the device ----------------------------

// 100,000 instances of one triangle, all in one place, and one ray: the
// model's exact tier weighs every pair of tied hits (runs for minutes).
std::string slowModelCase() {
  std::string text =
      "rules: [R-TIE]\nscene:\n  blas:\n    tri:\n      - triangles:\n          vertices: [[-1, "
      "-1, 0], [1, -1, 0], [0, 1, 0]]\n  instances:\n";
  for (int i = 0; i < 100000; ++i) text += "    - {blas: tri}\n";
  text +=
      "rays:\n  list:\n    - {origin: [0, 0, 5], direction: [0, 0, -1]}\npipeline:\n  miss:\n    - "
      "[count: miss]\n  hit_groups:\n    - closest_hit: [count: closesthit, record: [hit, "
      "instance_id]]\noutputs:\n  counters: [miss, closesthit]\n  per_ray: [hit, instance_id]\n";
  return text;
}

TEST(ModelIsolation, ModelPastTheTimeoutIsATimeoutAndTheRunGoesOn) {
  const std::string out = fresh("model-timeout");
  const std::string slow = writeCase(out, "many-instances", slowModelCase());
  const auto start = Clock::now();
  const int rc = sh(kBin + " run --no-validation --timeout 3 --case " + slow +
                        caseArg("results/miss-xor-closest-hit") + " --out " + out + "/run",
                    out + "/log.txt");
  EXPECT_LT(since(start), 60.0);
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  const nlohmann::json summary = summaryOf(out + "/run");
  const auto [status, headline] = caseIn(summary, "many-instances");
  EXPECT_EQ(status, "Timeout") << slurp(out + "/log.txt");
  EXPECT_EQ(headline.rfind("Timeout: model: ", 0), 0u) << headline;
  EXPECT_NE(headline.find("the model process ran longer than 3 s"), std::string::npos) << headline;
  EXPECT_EQ(caseIn(summary, "results/miss-xor-closest-hit").first, "Pass");
}

TEST(ModelIsolation, ModelOverTheMemoryLimitIsACrash) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer build: no memory limit is set on children";
#endif
  const std::string out = fresh("model-memory");
  // 256 MiB, the least --memory-limit takes, is too little for this case's model.
  const int rc = sh(kBin + " run --no-device --memory-limit 256M" +
                        caseArg("model/mixed-scene-1024") + " --out " + out,
                    out + "/log.txt");
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  const auto [status, headline] = caseIn(summaryOf(out), "model/mixed-scene-1024");
  EXPECT_EQ(status, "Crash");
  EXPECT_EQ(headline.rfind("Crash: model: ", 0), 0u) << headline;
}

// ---- items 4 and 5: the case is at fault -----------------------------------

TEST(CaseErrors, CaseFileErrorsAreCaseErrorsAndTheRunGoesOn) {
  const std::string out = fresh("case-file-errors");
  const std::string broken = writeCase(out, "broken", "rules: [R-IGNORE]\nscene: 12\n");
  const std::string unknown_rule =
      writeCase(out, "unknown-rule",
                editedCase("results/miss-xor-closest-hit", "rules: [", "rules: [R-NO-SUCH-RULE, "));
  const int rc = sh(kBin + " run --no-validation --case " + broken + " --case " + unknown_rule +
                        caseArg("results/miss-xor-closest-hit") + " --out " + out + "/run",
                    out + "/log.txt");
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  const nlohmann::json summary = summaryOf(out + "/run");
  const auto [broken_status, broken_headline] = caseIn(summary, "broken");
  EXPECT_EQ(broken_status, "CaseError");
  EXPECT_NE(broken_headline.find("broken.yaml:"), std::string::npos)
      << "file, line, column: " << broken_headline;
  const auto [rule_status, rule_headline] = caseIn(summary, "unknown-rule");
  EXPECT_EQ(rule_status, "CaseError");
  EXPECT_NE(rule_headline.find("R-NO-SUCH-RULE"), std::string::npos) << rule_headline;
  EXPECT_EQ(caseIn(summary, "results/miss-xor-closest-hit").first, "Pass");
  EXPECT_EQ(summary["counts"]["CaseError"], 2);
  EXPECT_EQ(summary["counts"]["Fail"], 0);
}

TEST(CaseErrors, TooLongImageNameIsACaseErrorAndTheReportsAreWritten) {
  const std::string out = fresh("long-image-name");
  const std::string long_name(300, 'i');
  const std::string path =
      writeCase(out, "long-image",
                editedCase("results/miss-xor-closest-hit", "{name: hit, from: hit}",
                           "{name: " + long_name + ", from: hit}"));
  const int rc = sh(kBin + " run --no-validation --case " + path +
                        caseArg("anyhit/ignore-odd-primitives") + " --out " + out + "/run",
                    out + "/log.txt");
  EXPECT_EQ(rc, 1) << slurp(out + "/log.txt");
  const nlohmann::json summary = summaryOf(out + "/run");
  EXPECT_EQ(caseIn(summary, "long-image").first, "CaseError") << slurp(out + "/log.txt");
  EXPECT_EQ(caseIn(summary, "anyhit/ignore-odd-primitives").first, "Pass");
  EXPECT_FALSE(summary["interrupted"].get<bool>());
  EXPECT_TRUE(fs::exists(out + "/run/report.html"));
  EXPECT_EQ(summary["counts"]["Crash"], 0) << "the device is not blamed";
}

// ---- item 6: exit statuses -------------------------------------------------

TEST(ExitCodes, NoSuchDeviceStopsBeforeTheCasesAndNamesTheDevices) {
  for (const char* isolation : {"", " --no-isolation"}) {
    SCOPED_TRACE(isolation);
    const std::string out = fresh("no-such-device");
    const int rc = sh(kBin + " run --no-validation --device nosuchdevice" + isolation +
                          caseArg("results/miss-xor-closest-hit") + " --out " + out + "/run",
                      out + "/log.txt");
    const std::string log = slurp(out + "/log.txt");
    EXPECT_EQ(rc, 2) << log;
    EXPECT_NE(log.find("'nosuchdevice'"), std::string::npos) << log;
    EXPECT_NE(log.find("devices:"), std::string::npos) << log;
    EXPECT_NE(log.find("llvmpipe"), std::string::npos) << "the devices there are: " << log;
    EXPECT_FALSE(fs::exists(out + "/run/results.csv")) << "no case ran";
  }
}

TEST(ExitCodes, NothingComparedIsNotASuccess) {
  const std::string out = fresh("nothing-compared");
  // The model alone: no device, so not ctest's skip either.
  EXPECT_EQ(sh(kBin + " run --no-device" + caseArg("results/miss-xor-closest-hit") + " --out " +
                   out + "/one",
               out + "/one.txt"),
            3)
      << slurp(out + "/one.txt");
  EXPECT_EQ(sh(kBin + " run --no-device" + caseArg("results/miss-xor-closest-hit") +
                   caseArg("anyhit/ignore-odd-primitives") + " --out " + out + "/two",
               out + "/two.txt"),
            3);
  EXPECT_NE(slurp(out + "/two.txt").find("nothing was compared"), std::string::npos);
}

TEST(ExitCodes, CompareWithAMissingOrEmptyReferenceIsAnError) {
  const std::string out = fresh("compare-missing");
  ASSERT_EQ(sh(kBin + " run --no-validation" + caseArg("results/miss-xor-closest-hit") + " --out " +
                   out + "/run",
               out + "/run.txt"),
            0)
      << slurp(out + "/run.txt");
  EXPECT_EQ(sh(kBin + " compare " + out + "/run " + out + "/missing-folder --out " + out + "/c1",
               out + "/c1.txt"),
            2);
  EXPECT_NE(slurp(out + "/c1.txt").find("missing-folder is not a folder"), std::string::npos)
      << slurp(out + "/c1.txt");
  fs::create_directories(out + "/empty");
  EXPECT_EQ(
      sh(kBin + " compare " + out + "/run " + out + "/empty --out " + out + "/c2", out + "/c2.txt"),
      3);
  EXPECT_NE(slurp(out + "/c2.txt").find("nothing was compared"), std::string::npos)
      << slurp(out + "/c2.txt");
}

// A case re-run under a baseline keeps its re-run in <case>/rerun/device:
// compared, it is that case's, not a case of its own (it was counted as
// one, NotSupported for want of a counterpart). --brief lists nothing that
// passes.
TEST(ExitCodes, CompareCountsACasesRerunAsThatCase) {
  const std::string out = fresh("compare-rerun");
  const std::string name = "results/miss-xor-closest-hit";
  ASSERT_EQ(sh(kBin + " run --no-validation" + caseArg(name) + " --out " + out + "/run",
               out + "/run.txt"),
            0)
      << slurp(out + "/run.txt");
  fs::create_directories(out + "/run/" + name + "/rerun");
  fs::copy(out + "/run/" + name + "/device", out + "/run/" + name + "/rerun/device",
           fs::copy_options::recursive);
  fs::copy(out + "/run", out + "/reference", fs::copy_options::recursive);
  ASSERT_EQ(sh(kBin + " compare --brief " + out + "/run " + out + "/reference --out " + out + "/c",
               out + "/c.txt"),
            0)
      << slurp(out + "/c.txt");
  EXPECT_EQ(readDeqpCsv(out + "/c/results.csv").size(), 1u) << slurp(out + "/c/results.csv");
  EXPECT_EQ(slurp(out + "/c.txt").find(name), std::string::npos)
      << "--brief: a passing case is not listed\n"
      << slurp(out + "/c.txt");
}

// ---- item 7: ray lists up to the device's limits ---------------------------

// 40,000 rays (beyond lavapipe's maxImageDimension2D of 16,384) in a list,
// over a grid of triangles, with an image of what each ray hit.
std::string longListCase() {
  std::string text =
      "rules: [R-MISS-XOR-CHIT]\nscene:\n  blas:\n    grid:\n      - triangles: {grid: {cells: [8, "
      "8], size: [2, 2], center: [0, 0, 0]}}\n        flags: [opaque]\n  instances:\n    - {blas: "
      "grid}\nrays:\n  tmin: 0.001\n  tmax: 100\n  list:\n";
  for (int i = 0; i < 40000; ++i) {
    const double x = -1.5 + 3.0 * ((i % 200) + 0.37) / 200,
                 y = -1.5 + 3.0 * ((i / 200) + 0.41) / 200;
    text += "    - {origin: [" + std::to_string(x) + ", " + std::to_string(y) +
            ", 5], direction: [0, 0, -1]}\n";
  }
  text +=
      "pipeline:\n  miss:\n    - [count: miss, record: {hit: 0}]\n  hit_groups:\n    - "
      "closest_hit: [count: closesthit, record: [hit, primitive_id, hit_t]]\noutputs:\n  counters: "
      "[miss, closesthit]\n  per_ray: [hit, primitive_id, hit_t]\n  images:\n    - {name: "
      "primitive, from: primitive_id}\n";
  return text;
}

TEST(LongRayLists, ListOf40000RaysWithAnImagePassesUnderValidation) {
  const std::string out = fresh("long-ray-list");
  const std::string path = writeCase(out, "long-list", longListCase());
  const int rc = sh(kBin + " run --strict-validation --case " + path + " --out " + out + "/run",
                    out + "/log.txt");
  EXPECT_EQ(rc, 0) << slurp(out + "/log.txt");
  const nlohmann::json summary = summaryOf(out + "/run");
  EXPECT_EQ(caseIn(summary, "long-list").first, "Pass") << caseIn(summary, "long-list").second;
  EXPECT_TRUE(summary["validation"].get<bool>());
}

}  // namespace

namespace {

// A Vulkan call that fails on one case (planted: the driver loses the device,
// runs out of memory, refuses the pipeline) gives that case its status, and
// the run goes on: the other case passes, in a child process or on the one
// device of --no-isolation.
TEST(DeviceErrors, TheFailingCaseGetsItsStatusAndTheRunGoesOn) {
  struct Expect {
    const char* fault;
    const char* status;
    const char* headline;
    int exit;
  };
  const Expect expects[] = {
      {"device-lost", "Crash", "device lost: vkWaitForFences returned VK_ERROR_DEVICE_LOST", 1},
      {"out-of-device-memory", "NotSupported",
       "out of memory: vkAllocateMemory returned VK_ERROR_OUT_OF_DEVICE_MEMORY", 0},
      {"pipeline-refused", "Fail", "the driver refused the pipeline", 1}};
  for (const Expect& e : expects)
    for (const std::string isolation : {"", " --no-isolation"}) {
      const std::string out =
          fresh(std::string("device-error-") + e.fault + (isolation.empty() ? "" : "-in-process"));
      const int status =
          sh(kBin + " run" + caseArg("sbt/hit-group-index") +
                 caseArg("results/miss-xor-closest-hit") + " --plant-fault " + e.fault +
                 " --plant-fault-in sbt/hit-group-index --out " + out + isolation,
             out + "/log");
      const std::string what = std::string(e.fault) + isolation;
      EXPECT_EQ(status, e.exit) << what << "\n" << slurp(out + "/log");
      const nlohmann::json summary = summaryOf(out);
      const auto [faulted, headline] = caseIn(summary, "sbt/hit-group-index");
      EXPECT_EQ(faulted, e.status) << what;
      EXPECT_NE(headline.find(e.headline), std::string::npos) << what << ": " << headline;
      EXPECT_EQ(caseIn(summary, "results/miss-xor-closest-hit").first, "Pass") << what;
    }
}

}  // namespace

// --filter given twice runs the cases either glob matches, and no more; when
// neither matches, the error names both.
TEST(RunFilter, SeveralGlobsRunTheCasesOfEach) {
  const std::string out = fresh("run-filters");
  const std::string cases = " --cases " + cli::kCases;
  // Only the model runs: every case is NotSupported, the run not refused (2).
  EXPECT_NE(sh(kBin + " run --no-device" + cases +
                   " --filter 'ray-query/compute-*' --filter 'anyhit/unused-any-hit' --out " + out,
               out + "/log.txt"),
            2)
      << slurp(out + "/log.txt");
  std::set<std::string> names;
  const nlohmann::json summary = summaryOf(out);
  for (const auto& c : summary["cases"]) names.insert(c["name"].get<std::string>());
  EXPECT_EQ(names,
            (std::set<std::string>{
                "anyhit/unused-any-hit", "ray-query/compute-any-hit-and-intersection",
                "ray-query/compute-closest-hit-and-miss", "ray-query/compute-query-in-loop"}));
  const std::string none = fresh("run-filters-none");
  EXPECT_NE(sh(kBin + " run --no-device" + cases + " --filter 'x/*' --filter 'y/*' --out " + none,
               none + "/log.txt"),
            0);
  EXPECT_NE(slurp(none + "/log.txt").find("no case matches 'x/*' or 'y/*'"), std::string::npos)
      << slurp(none + "/log.txt");
}
