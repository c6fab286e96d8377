// Pipelines created through a VkDeferredOperationKHR
// (VK_KHR_deferred_host_operations; pipeline.deferred, --through deferred,
// R-DEFERRED). The create call answers VK_OPERATION_DEFERRED_KHR (the work
// waits for threads to join it), VK_OPERATION_NOT_DEFERRED_KHR (done; its
// result is the operation's) or any other result, as if not deferred.
// Joined work goes on in each thread until the driver tells it
// VK_THREAD_DONE_KHR (no more work for it; others finish) or VK_SUCCESS (the
// operation is complete); VK_THREAD_IDLE_KHR means work may come later, so
// the thread joins again. Only then is the result read
// (vkGetDeferredOperationResultKHR, VK_NOT_READY until complete) and the
// pipeline handle used.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>

#include "base/result.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

// One operation's entry points: the driver's, or a test's scripted driver.
struct DeferredCalls {
  std::function<VkResult()> join;             // vkDeferredOperationJoinKHR
  std::function<VkResult()> result;           // vkGetDeferredOperationResultKHR
  std::function<uint32_t()> max_concurrency;  // vkGetDeferredOperationMaxConcurrencyKHR
};

// What joining one operation saw: the threads that joined, the answers of
// their joins, and the operation's result.
struct DeferredJoin {
  uint32_t threads = 0;
  uint32_t idle = 0, done = 0, success = 0, failed = 0;
  VkResult result = VK_SUCCESS;
};

// The threads that join: `threads`, or for 0 the operation's maximum
// concurrency; 1 to kMaxDeferredThreads.
uint32_t deferredThreadCount(uint32_t threads, uint32_t max_concurrency);

// Joins a deferred operation with deferredThreadCount(threads, ...) threads,
// each until the driver says it is done, then reads the operation's result
// until it is ready.
DeferredJoin joinDeferred(const DeferredCalls& calls, uint32_t threads);

// The pipeline `create` makes given a deferred operation (it writes the
// handle into `slot`), the operation joined by `threads` threads (0: its
// maximum concurrency); or the Device error of the create call or the
// operation, named `what`.
Result<VkPipeline> createDeferred(const VulkanContext& ctx, uint32_t threads, const char* what,
                                  const std::function<VkResult(VkDeferredOperationKHR)>& create,
                                  VkPipeline& slot, Cleanup& cleanup);

}  // namespace rayspec
