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

namespace rayspec {

enum class CostStep {
  // the parent
  Parse,       // reading and parsing the case file (sweep expansion included)
  Plan,        // deriving the plan
  Process,     // a child's start and end: the side's wall time less the steps it reported
  ReadBundle,  // reading a side's results bundle back
  ImageFiles,  // PNG / EXR files of a side's images
  Comparison,  // judging the case (compare, verdict, diff images, failing rays)
  Reports,     // rewriting the run's reports with the case
  RecordsCsv,  // records.csv of both sides (a case that did not pass, or --records-csv)
  // either side, in its process
  BackendSetup,  // making the backend: Vulkan instance and device (validation layer); nothing much
                 // for the model
  BackendTeardown,  // closing it (device destruction, the layer's last messages)
  WriteBundle,      // writing the results bundle
  // the device
  GlslGeneration,     // the stage programs as GLSL
  SpirvCompile,       // glslang + SPIRV-Tools, SPIR-V cache miss
  SpirvCacheHit,      // SPIR-V taken from the cache
  PipelineCreation,   // vkCreateRayTracingPipelinesKHR (shader modules included)
  Buffers,            // case buffers, descriptor set and layouts
  AccelerationBuild,  // BLAS + TLAS builds, recorded and waited on
  Sbt,                // group handles and the shader binding table
  Trace,              // vkCmdTraceRaysKHR, recorded and waited on
  ReadBack,           // records, counters and images to host memory
  CaseCleanup,        // waiting for the device and destroying the case's objects
  // the model
  ModelScene,  // Embree scene and the programs
  ModelTrace,  // every ray through the model
};
inline constexpr size_t kCostSteps = static_cast<size_t>(CostStep::ModelTrace) + 1;

// Stable name ("spirv_compile"); parseCostStep reads it back.
const char* costStepName(CostStep s);
bool parseCostStep(const std::string& name, CostStep* out);

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
enum class CostSide { Parent, Model, Device };
inline constexpr size_t kCostSides = 3;
const char* costSideName(CostSide s);  // "parent", "model", "device"

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
