#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

InjectedVkError& injected() {
  static InjectedVkError e;
  return e;
}

}  // namespace

void injectVkError(const InjectedVkError& e) {
  injected() = e;
}

std::optional<VkResult> injectedVkError(const char* call) {
  if (injected().call.empty() || injected().call != call) return std::nullopt;
  return injected().result;
}

}  // namespace rayspec
