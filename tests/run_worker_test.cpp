// Long-lived workers (run/worker.h, SideWorker in run/isolation.h): many
// requests in one process; a request that crashes, hangs, throws or runs out
// of memory costs only itself, and the next one gets a new process.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "parse/parse_case.h"
#include "plan/plan.h"
#include "run/case_steps.h"
#include "run/isolation.h"
#include "run/model_adapter.h"
#include "run/worker.h"
#include "suite_cases.h"
#include "temp_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

// A worker that answers with its pid, and misbehaves on request.
Worker::Serve misbehaving() {
  return [](const std::string& request) -> Result<std::string> {
    if (request == "crash") raise(SIGSEGV);
    if (request == "hang")
      for (;;) pause();
    if (request == "fail") return errorMessage("bad request");
    if (request == "throw") return std::to_string(std::stoul("no number"));  // the library throws
    if (request == "hog") {
      std::vector<std::vector<char>> held;
      for (;;) held.emplace_back(64u << 20, 'x');
    }
    if (request == "shared-hog") {  // shared mappings: RLIMIT_DATA does not count them
      for (;;) {
        void* p =
            mmap(nullptr, 64u << 20, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) return std::string("mmap failed");
        std::memset(p, 'x', 64u << 20);
      }
    }
    return std::to_string(getpid());
  };
}

TEST(Worker, ManyRequestsOneProcess) {
  Worker w(
      misbehaving(), [] { return std::string("finished"); }, ChildLimits{30, 0});
  const Worker::Reply a = w.call("pid"), b = w.call("pid");
  ASSERT_TRUE(a.replied && b.replied);
  EXPECT_EQ(a.text, b.text);
  EXPECT_NE(a.text, std::to_string(getpid())) << "served in this process";
  EXPECT_EQ(w.started(), 1);
  EXPECT_EQ(w.close(), "finished");
  EXPECT_FALSE(w.running());
}

TEST(Worker, CrashCostsOnlyItsRequest) {
  Worker w(misbehaving(), {}, ChildLimits{30, 0});
  const std::string first = w.call("pid").text;
  const Worker::Reply crash = w.call("crash");
  EXPECT_FALSE(crash.replied);
  EXPECT_EQ(crash.end.how, ChildEnd::How::Signaled);
  EXPECT_EQ(crash.end.code, SIGSEGV);
  const Worker::Reply after = w.call("pid");
  ASSERT_TRUE(after.replied);
  EXPECT_NE(after.text, first) << "the request after a crash runs in a new process";
  EXPECT_EQ(w.started(), 2);
}

TEST(Worker, HangIsKilledAtTheTimeout) {
  Worker w(misbehaving(), {}, ChildLimits{0.5, 0});
  const auto start = std::chrono::steady_clock::now();
  const Worker::Reply hang = w.call("hang");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_FALSE(hang.replied);
  EXPECT_EQ(hang.end.how, ChildEnd::How::TimedOut);
  EXPECT_TRUE(w.call("pid").replied);
}

TEST(Worker, ErrorOrExceptionIsAReplyAndTheProcessGoesOn) {
  Worker w(misbehaving(), {}, ChildLimits{30, 0});
  const std::string first = w.call("pid").text;
  const Worker::Reply failed = w.call("fail");
  EXPECT_TRUE(failed.replied);
  EXPECT_TRUE(failed.failed);
  EXPECT_EQ(failed.text, "bad request");
  const Worker::Reply thrown = w.call("throw");
  EXPECT_TRUE(thrown.replied);
  EXPECT_TRUE(thrown.failed);
  EXPECT_EQ(thrown.text, "stoul");
  EXPECT_EQ(w.call("pid").text, first);
}

TEST(WorkerMemoryLimit, OutOfMemoryEndsTheProcessWithItsStatus) {
  if (!memoryLimitApplies())
    GTEST_SKIP() << "AddressSanitizer build: no memory limit is set on children";
  Worker w(misbehaving(), {}, ChildLimits{60, 256u << 20});
  const Worker::Reply hog = w.call("hog");
  EXPECT_FALSE(hog.replied);
  EXPECT_EQ(hog.end.how, ChildEnd::How::Exited);
  EXPECT_EQ(hog.end.code, kChildOutOfMemory);
  EXPECT_TRUE(w.call("pid").replied);
}

// Shared mappings (as lavapipe makes) are outside RLIMIT_DATA: the parent's
// watch of the resident set ends the worker all the same (issue 44: a worker
// under --memory-limit 8G reached 13.5 GB).
TEST(WorkerMemoryLimit, SharedMappingsCountToo) {
  if (!memoryLimitApplies())
    GTEST_SKIP() << "AddressSanitizer build: no memory limit is set on children";
  Worker w(misbehaving(), {}, ChildLimits{60, 256u << 20});
  const Worker::Reply hog = w.call("shared-hog");
  EXPECT_FALSE(hog.replied) << hog.text;
  EXPECT_EQ(hog.end.how, ChildEnd::How::Exited);
  EXPECT_EQ(hog.end.code, kChildOutOfMemory);
  EXPECT_TRUE(w.call("pid").replied);
}

// A second worker holds no copy of the first one's socket: closing the first
// ends it at once, while the second still runs.
TEST(Worker, ClosingOneWorkerIsSeenByItAlone) {
  Worker a(
      misbehaving(), [] { return std::string("a done"); }, ChildLimits{5, 0});
  ASSERT_TRUE(a.call("pid").replied);
  Worker b(
      misbehaving(), [] { return std::string("b done"); }, ChildLimits{5, 0});
  ASSERT_TRUE(b.call("pid").replied);
  EXPECT_EQ(a.close(), "a done");
  EXPECT_EQ(b.close(), "b done");
}

// The model side of three cases in one worker; the middle one crashes it
// (a planted crash), the last runs in a new worker and passes.
TEST(SideWorker, CrashedCaseIsACrashAndTheNextCaseGetsANewWorker) {
  const std::vector<Case> cases{suiteCaseFile("results/miss-xor-closest-hit"),
                                suiteCaseFile("anyhit/ignore-odd-primitives"),
                                suiteCaseFile("results/miss-xor-closest-hit")};
  const SideFor side_for = [](const Case&, const std::string& dir) -> Result<Side> {
    Side s{"model", "model", [] { return std::make_unique<ModelAdapter>(ModelOptions{}); }, {}};
    if (dir.find("/crash/") != std::string::npos)
      s.before = [] {
        raise(SIGSEGV);
      };
    return s;
  };
  SideWorker worker("model", "model", cases, side_for, ChildLimits{60, 0});
  const std::string dir = freshTempDir("rayspec-worker-test/side");
  const SideResult first = *worker.run(0, derivePlan(cases[0]), dir + "/ok/0/model");
  EXPECT_TRUE(first.results.ok()) << first.results.statusText();
  const SideResult crashed = *worker.run(1, derivePlan(cases[1]), dir + "/crash/1/model");
  EXPECT_EQ(crashed.results.status, SideStatus::Crash);
  EXPECT_NE(crashed.results.status_detail.find("signal 11"), std::string::npos)
      << crashed.results.status_detail;
  EXPECT_EQ(crashed.results.case_name, "anyhit/ignore-odd-primitives")
      << "the crash is the case that ran";
  const SideResult last = *worker.run(2, derivePlan(cases[2]), dir + "/ok/2/model");
  EXPECT_TRUE(last.results.ok()) << last.results.statusText();
  EXPECT_EQ(worker.processesStarted(), 2);
  EXPECT_TRUE(worker.close().empty());
}

}  // namespace
}  // namespace rayspec
