// Pipelines created through a deferred operation (pipeline.deferred,
// R-DEFERRED): the joins against a scripted driver that defers (lavapipe
// 25.0.7 does not: it creates the pipeline inside the create call and
// answers VK_SUCCESS), the thread count, and the field's parse errors. The
// device side runs in anyhit/deferred-creation and --through deferred.
#include <gtest/gtest.h>

#include <mutex>

#include "parse/parse_case.h"
#include "vulkan/deferred_operation.h"

namespace rayspec {
namespace {

// A driver holding `work` pieces of work: each join past the first `idle`
// ones (VK_THREAD_IDLE_KHR: work may come later) takes a piece while any is
// left and answers VK_THREAD_DONE_KHR, or VK_SUCCESS once the operation is
// complete. The operation completes `finishing` result reads after the last
// piece was taken (VK_NOT_READY until then); a result read while work is
// left, past 1000 of them, answers VK_ERROR_UNKNOWN (the work was never
// joined).
struct ScriptedDriver {
  std::mutex m;
  int work = 0, idle = 0, finishing = 0, unjoined_reads = 0;
  bool complete = false;

  VkResult join() {
    std::lock_guard<std::mutex> lock(m);
    if (idle > 0) return --idle, VK_THREAD_IDLE_KHR;
    if (work > 0 && --work == 0 && finishing == 0) complete = true;
    return complete ? VK_SUCCESS : VK_THREAD_DONE_KHR;
  }
  VkResult result() {
    std::lock_guard<std::mutex> lock(m);
    if (work > 0) return ++unjoined_reads > 1000 ? VK_ERROR_UNKNOWN : VK_NOT_READY;
    if (!complete && --finishing <= 0) complete = true;
    return complete ? VK_SUCCESS : VK_NOT_READY;
  }
  DeferredCalls calls(uint32_t max_concurrency) {
    return {[this] { return join(); }, [this] { return result(); },
            [max_concurrency] {
              return max_concurrency;
            }};
  }
};

TEST(DeferredOperation, IdleJoinsJoinAgainAndTheResultIsWaitedFor) {
  ScriptedDriver d;
  d.work = 1;
  d.idle = 3;
  d.finishing = 2;
  const DeferredJoin j = joinDeferred(d.calls(1), 1);
  EXPECT_EQ(j.threads, 1u);
  EXPECT_EQ(j.idle, 3u);  // the join went on past each VK_THREAD_IDLE_KHR
  EXPECT_EQ(j.result, VK_SUCCESS);
  EXPECT_TRUE(d.complete);  // not read while VK_NOT_READY
}

TEST(DeferredOperation, EveryThreadJoinsUntilItIsDone) {
  ScriptedDriver d;
  d.work = 3;
  const DeferredJoin j = joinDeferred(d.calls(64), 8);
  EXPECT_EQ(j.threads, 8u);
  EXPECT_EQ(j.done + j.success + j.failed, 8u);  // each thread joined to its end
  EXPECT_EQ(j.failed, 0u);
  EXPECT_EQ(j.result, VK_SUCCESS);
  EXPECT_EQ(d.work, 0);
}

TEST(DeferredOperation, MaxMeansTheOperationsConcurrencyWithinTheLimit) {
  EXPECT_EQ(deferredThreadCount(0, 3), 3u);
  EXPECT_EQ(deferredThreadCount(0, 0), 1u);
  EXPECT_EQ(deferredThreadCount(0, UINT32_MAX), kMaxDeferredThreads);
  EXPECT_EQ(deferredThreadCount(2, 1), 2u);  // a count asked for is kept
}

ParseResult parseDeferred(const std::string& deferred) {
  return parseCaseText(
      "rules: [R-DEFERRED]\nrays:\n  list: [{origin: [0, 0, 1], direction: [0, 0, "
      "-1]}]\npipeline:\n  deferred: " +
          deferred + "\n  miss: [[count: miss]]\noutputs:\n  counters: [miss]\n",
      "t.yaml", "t/t");
}

TEST(DeferredOperation, ThreadsParseAndAreChecked) {
  const ParseResult two = parseDeferred("{threads: 2}");
  ASSERT_TRUE(two.value) << (two.errors.empty() ? "" : two.errors[0].format());
  EXPECT_EQ(two.value->pipeline.deferred_threads, 2u);
  const ParseResult max = parseDeferred("{threads: max}");
  ASSERT_TRUE(max.value);
  EXPECT_EQ(max.value->pipeline.deferred_threads, 0u);
  for (const std::string bad : {"{threads: 0}", "{threads: 65}", "{threads: many}", "{}", "2"}) {
    const ParseResult r = parseDeferred(bad);
    ASSERT_FALSE(r.errors.empty()) << bad;
    EXPECT_NE(r.errors[0].format().find("t.yaml:5"), std::string::npos) << r.errors[0].format();
    EXPECT_NE(r.errors[0].format().find("pipeline.deferred"), std::string::npos)
        << r.errors[0].format();
  }
}

}  // namespace
}  // namespace rayspec
