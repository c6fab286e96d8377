#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

InjectedVkError& injected() {
  static InjectedVkError e;
  return e;
}

LayoutFault& injectedLayout() {
  static LayoutFault f = LayoutFault::None;
  return f;
}

}  // namespace

void injectVkError(const InjectedVkError& e) {
  injected() = e;
}

std::optional<VkResult> injectedVkError(const char* call) {
  if (injected().call.empty() || injected().call != call) return std::nullopt;
  return injected().result;
}

void injectLayoutFault(LayoutFault f) {
  injectedLayout() = f;
}

LayoutFault injectedLayoutFault() {
  return injectedLayout();
}

std::optional<LayoutFault> layoutFault(const std::string& name) {
  const std::optional<LayoutFault> f = valueNamed<LayoutFault>(name);
  if (f == LayoutFault::None) return std::nullopt;
  return f;
}

const std::vector<std::string>& layoutFaultNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& row : enumNames<LayoutFault>())
      if (row.value != LayoutFault::None) out.push_back(row.name);
    return out;
  }();
  return names;
}

}  // namespace rayspec
