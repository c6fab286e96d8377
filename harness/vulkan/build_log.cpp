#include "vulkan/build_log.h"

#include <optional>

namespace rayspec {
namespace {

std::optional<BuildLog>& theLog() {
  static std::optional<BuildLog> log;
  return log;
}

}  // namespace

void recordBuildLog(bool on) {
  if (on)
    theLog().emplace();
  else
    theLog().reset();
}

BuildLog* buildLog() {
  return theLog() ? &*theLog() : nullptr;
}

}  // namespace rayspec
