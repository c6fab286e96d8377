// What each step of a case costs, in seconds of wall time. Every side (the
// parent, the model's process, the device's process) fills one StepCosts;
// the sides' own steps travel in their results bundle (results.json "cost"),
// the parent joins them into <out>/<case>/cost.json and the run's totals
// (summary.json "cost", summary.txt).
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string>

#include "base/enum_names.h"

namespace rayspec {

#define RAYSPEC_COST_STEPS(X)                                                                      \
  /* the parent */                                                                                 \
  X(Parse, "parse") /* reading and parsing the case file (sweep expansion included) */             \
  X(Plan, "plan")   /* deriving the plan */                                                        \
  X(Process,                                                                                       \
    "process") /* a child's start and end: the side's wall time less the steps it reported */      \
  X(ReadBundle, "read_bundle") /* reading a side's results bundle back */                          \
  X(ImageFiles, "image_files") /* PNG / EXR files of a side's images */                            \
  X(Comparison, "comparison") /* judging the case (compare, verdict, diff images, failing rays) */ \
  X(Reports, "reports")       /* rewriting the run's reports with the case */                      \
  X(RecordsCsv,                                                                                    \
    "records_csv") /* records.csv of both sides (a case that did not pass, or --records-csv) */    \
  /* either side, in its process */                                                                \
  X(BackendSetup, "backend_setup") /* making the backend: Vulkan instance and device (validation   \
                                      layer); nothing much */                                      \
  /* for the model */                                                                              \
  X(BackendTeardown,                                                                               \
    "backend_teardown")          /* closing it (device destruction, the layer's last messages) */  \
  X(WriteBundle, "write_bundle") /* writing the results bundle */                                  \
  /* the device */                                                                                 \
  X(GlslGeneration, "glsl_generation") /* the stage programs as GLSL */                            \
  X(SpirvCompile, "spirv_compile")     /* glslang + SPIRV-Tools, SPIR-V cache miss */              \
  X(SpirvCacheHit, "spirv_cache_hit")  /* SPIR-V taken from the cache */                           \
  X(PipelineCreation,                                                                              \
    "pipeline_creation") /* vkCreateRayTracingPipelinesKHR (shader modules included) */            \
  X(Buffers, "buffers")  /* case buffers, descriptor set and layouts */                            \
  X(AccelerationBuild, "acceleration_build") /* BLAS + TLAS builds, recorded and waited on */      \
  X(Sbt, "sbt")                              /* group handles and the shader binding table */      \
  X(Trace, "trace")                          /* vkCmdTraceRaysKHR, recorded and waited on */       \
  X(ReadBack, "read_back")                   /* records, counters and images to host memory */     \
  X(CaseCleanup, "case_cleanup") /* waiting for the device and destroying the case's objects */    \
  /* the model */                                                                                  \
  X(ModelScene, "model_scene") /* Embree scene and the programs */                                 \
  X(ModelTrace, "model_trace") /* every ray through the model */
enum class CostStep { RAYSPEC_COST_STEPS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(CostStep, RAYSPEC_COST_STEPS);
inline constexpr size_t kCostSteps = enumCount<CostStep>();

// Stable name ("spirv_compile"); parseCostStep reads it back.
inline const char* costStepName(CostStep s) {
  return nameOf(s);
}
inline bool parseCostStep(const std::string& name, CostStep* out) {
  return parseEnumName(name, out);
}

struct StepCosts {
  std::array<double, kCostSteps> seconds{};
  double& operator[](CostStep s) { return seconds[static_cast<size_t>(s)]; }
  double operator[](CostStep s) const { return seconds[static_cast<size_t>(s)]; }
  void add(CostStep s, double sec) { (*this)[s] += sec; }
  double total() const;
  StepCosts& operator+=(const StepCosts& other);
};

// Who spent the time: the parent (the run loop), or a side (its process's
// own steps, plus what the parent spent on it: process, read_bundle,
// image_files).
#define RAYSPEC_COST_SIDES(X) X(Parent, "parent") X(Model, "model") X(Device, "device")
enum class CostSide { RAYSPEC_COST_SIDES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(CostSide, RAYSPEC_COST_SIDES);
inline constexpr size_t kCostSides = enumCount<CostSide>();
inline const char* costSideName(CostSide s) {
  return nameOf(s);
}

struct CaseCost {
  std::array<StepCosts, kCostSides> sides;
  StepCosts& operator[](CostSide s) { return sides[static_cast<size_t>(s)]; }
  const StepCosts& operator[](CostSide s) const { return sides[static_cast<size_t>(s)]; }
  double total() const;
  CaseCost& operator+=(const CaseCost& other);
};

// Adds the wall time from construction to stop() (or destruction) to one step.
class StepTimer {
 public:
  StepTimer(StepCosts* costs, CostStep step)
      : costs_(costs), step_(step), start_(std::chrono::steady_clock::now()) {}
  StepTimer(StepCosts& costs, CostStep step) : StepTimer(&costs, step) {}
  ~StepTimer() { stop(); }
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;
  // Ends the step (once; the destructor then adds nothing); returns its seconds.
  double stop();

 private:
  StepCosts* costs_;  // nullptr: nothing is recorded
  CostStep step_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace rayspec
