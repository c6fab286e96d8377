// R-STACK broken: a device that ignores the stack size the case sets
// (vkCmdSetRayTracingPipelineStackSizeKHR) and keeps the default stack, whose
// two callable frames cannot hold a third: a callable nested deeper does
// nothing (the model's test-only hook, model/model_faults.h).
#include "fault/fault_impl.h"

namespace rayspec {

std::string stackSizeIgnored(Case& c, ModelOptions& o) {
  o.faults.stack_size_ignored = true;
  const uint32_t depth = c.pipeline.callableDepth();
  if (depth <= kDefaultCallableDepth) return "";
  return "callables nested deeper than " + std::to_string(kDefaultCallableDepth) +
         " do nothing (the stack size set for " + std::to_string(depth) + " is ignored)";
}

}  // namespace rayspec
