#include "results/step_cost.h"

namespace rayspec {

const char* costStepName(CostStep s) {
  switch (s) {
    case CostStep::Parse:
      return "parse";
    case CostStep::Plan:
      return "plan";
    case CostStep::Process:
      return "process";
    case CostStep::ReadBundle:
      return "read_bundle";
    case CostStep::ImageFiles:
      return "image_files";
    case CostStep::Comparison:
      return "comparison";
    case CostStep::Reports:
      return "reports";
    case CostStep::RecordsCsv:
      return "records_csv";
    case CostStep::BackendSetup:
      return "backend_setup";
    case CostStep::BackendTeardown:
      return "backend_teardown";
    case CostStep::WriteBundle:
      return "write_bundle";
    case CostStep::GlslGeneration:
      return "glsl_generation";
    case CostStep::SpirvCompile:
      return "spirv_compile";
    case CostStep::SpirvCacheHit:
      return "spirv_cache_hit";
    case CostStep::PipelineCreation:
      return "pipeline_creation";
    case CostStep::Buffers:
      return "buffers";
    case CostStep::AccelerationBuild:
      return "acceleration_build";
    case CostStep::Sbt:
      return "sbt";
    case CostStep::Trace:
      return "trace";
    case CostStep::ReadBack:
      return "read_back";
    case CostStep::CaseCleanup:
      return "case_cleanup";
    case CostStep::ModelScene:
      return "model_scene";
    case CostStep::ModelTrace:
      return "model_trace";
  }
  return "?";
}

bool parseCostStep(const std::string& name, CostStep* out) {
  for (size_t i = 0; i < kCostSteps; ++i)
    if (name == costStepName(static_cast<CostStep>(i))) {
      *out = static_cast<CostStep>(i);
      return true;
    }
  return false;
}

double StepCosts::total() const {
  double t = 0;
  for (double s : seconds) t += s;
  return t;
}

StepCosts& StepCosts::operator+=(const StepCosts& other) {
  for (size_t i = 0; i < kCostSteps; ++i) seconds[i] += other.seconds[i];
  return *this;
}

const char* costSideName(CostSide s) {
  switch (s) {
    case CostSide::Parent:
      return "parent";
    case CostSide::Model:
      return "model";
    case CostSide::Device:
      return "device";
  }
  return "?";
}

double CaseCost::total() const {
  double t = 0;
  for (const StepCosts& s : sides) t += s.total();
  return t;
}

CaseCost& CaseCost::operator+=(const CaseCost& other) {
  for (size_t i = 0; i < kCostSides; ++i) sides[i] += other.sides[i];
  return *this;
}

double StepTimer::stop() {
  if (!costs_) return 0;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  costs_->add(step_, s);
  costs_ = nullptr;
  return s;
}

}  // namespace rayspec
