#include "vulkan/deferred_operation.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

struct JoinCounts {
  std::atomic<uint32_t> idle{0}, done{0}, success{0}, failed{0};
};

// One thread's share: joins until the driver says this thread is done or the
// operation complete (or a join fails); an idle answer joins again.
void joinUntilDone(const DeferredCalls& calls, JoinCounts& counts) {
  for (;;) {
    const VkResult r = calls.join();
    if (r == VK_THREAD_IDLE_KHR) {
      ++counts.idle;
      std::this_thread::yield();
      continue;
    }
    ++(r == VK_SUCCESS ? counts.success : r == VK_THREAD_DONE_KHR ? counts.done : counts.failed);
    return;
  }
}

// The operation's result, once it is ready (a thread told VK_THREAD_DONE_KHR
// may return before another completes it).
VkResult operationResult(const DeferredCalls& calls) {
  VkResult r = calls.result();
  while (r == VK_NOT_READY) {
    std::this_thread::yield();
    r = calls.result();
  }
  return r;
}

DeferredCalls driverCalls(const VulkanContext& ctx, VkDeferredOperationKHR op) {
  const DeviceFunctions& fn = ctx.fn;
  VkDevice device = ctx.device;
  return {[&fn, device, op] { return fn.deferredOperationJoin(device, op); },
          [&fn, device, op] { return fn.getDeferredOperationResult(device, op); },
          [&fn, device, op] {
            return fn.getDeferredOperationMaxConcurrency(device, op);
          }};
}

// The operation's result after the create call answered `answer`. A
// success not deferred is joined as well (each join answers VK_SUCCESS when
// nothing was deferred): the validation layer (Debian 12's) wraps the
// pipeline's handle only when a join or a result read sees the operation
// complete, and a handle used before that crashes in the driver.
VkResult finish(const DeferredCalls& calls, VkResult answer, uint32_t threads) {
  if (answer == VK_OPERATION_DEFERRED_KHR || answer == VK_SUCCESS)
    return joinDeferred(calls, threads).result;
  if (answer == VK_OPERATION_NOT_DEFERRED_KHR) return operationResult(calls);
  return answer;  // a failure, as if no operation was given
}

}  // namespace

uint32_t deferredThreadCount(uint32_t threads, uint32_t max_concurrency) {
  const uint32_t n = threads != 0 ? threads : max_concurrency;
  return std::clamp<uint32_t>(n, 1, kMaxDeferredThreads);
}

DeferredJoin joinDeferred(const DeferredCalls& calls, uint32_t threads) {
  DeferredJoin out;
  out.threads = deferredThreadCount(threads, calls.max_concurrency());
  JoinCounts counts;
  std::vector<std::thread> joined;
  for (uint32_t t = 0; t < out.threads; ++t)
    joined.emplace_back([&calls, &counts] { joinUntilDone(calls, counts); });
  for (std::thread& t : joined) t.join();
  out.idle = counts.idle;
  out.done = counts.done;
  out.success = counts.success;
  out.failed = counts.failed;
  out.result = operationResult(calls);
  return out;
}

Result<VkPipeline> createDeferred(const VulkanContext& ctx, uint32_t threads, const char* what,
                                  const std::function<VkResult(VkDeferredOperationKHR)>& create,
                                  VkPipeline& slot, Cleanup& cleanup) {
  VkDeferredOperationKHR op = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(ctx.fn.createDeferredOperation(ctx.device, nullptr, &op),
                           "vkCreateDeferredOperationKHR"));
  VkDevice device = ctx.device;
  Cleanup operation;  // destroyed once complete, on every path
  const PFN_vkDestroyDeferredOperationKHR destroy = ctx.fn.destroyDeferredOperation;
  operation.add([destroy, device, op] { destroy(device, op, nullptr); });
  const VkPipeline before = slot;
  const VkResult answer = vkAnswer(what, [&] { return create(op); });
  RAYSPEC_TRY_VOID(vkCheck(finish(driverCalls(ctx, op), answer, threads), what));
  // test only: the fault seam (a harness that took the handle early)
  if (injectedLayoutFault() == LayoutFault::DeferredHandleEarly) {
    const VkPipeline made = slot;
    cleanup.add([device, made] { vkDestroyPipeline(device, made, nullptr); });
    return before;
  }
  return slot;
}

}  // namespace rayspec
