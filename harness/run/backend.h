// One side of a case: something that runs a parsed case and returns Results.
// Two implementations, thin adapters over the real engines: VulkanAdapter
// (vulkan/vulkan_engine.h) and ModelAdapter (model/model_engine.h). The
// run loop and the isolation in a child process see only this interface.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

class Backend {
 public:
  virtual ~Backend() = default;
  // Short stable name: "vulkan" or "model" (Results::backend).
  virtual std::string name() const = 0;
  // For people: the device and driver, or the model's engine and tier.
  virtual std::string description() const = 0;
  // Runs one case: what the case did on the backend, a failure included, is
  // in the status of the Results. An Error is the harness's own
  // (ErrorKind::Harness: saved results that do not fit the case): the case
  // becomes a CaseError.
  virtual Result<Results> run(const Case& c, const Plan& plan) = 0;
  // Releases the engine; returns what went wrong while doing so (validation
  // errors the layer reports at device destruction).
  virtual std::vector<std::string> close() = 0;
};

// Makes a backend where it will run (in the child process when isolated:
// Vulkan must not be initialised before a fork).
using BackendFactory = std::function<std::unique_ptr<Backend>()>;

}  // namespace rayspec
