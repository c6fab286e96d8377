// What a run concluded about one case: the verdict, the times, and where its
// results bundles and images are, for every report.
#pragma once

#include <string>
#include <vector>

#include "compare/verdict.h"

namespace rayspec {

// One failing ray, device against model, for the per-ray tables of the report.
struct RayRow {
  uint32_t ray = 0, x = 0, y = 0;
  std::string field, device, model;
};

// How a case's status relates to the driver's baseline (report/baseline.h).
enum class BaselineMatch { None, Expected, UnexpectedPass };

struct CaseOutcome {
  std::string name;
  std::vector<std::string> rules;
  Status status = Status::Pass;
  std::string headline;
  double seconds = 0.0, device_seconds = 0.0, model_seconds = 0.0;
  Verdict verdict;
  std::vector<std::string> images;  // image names; files at <case>/{device,model,diff}/<name>.png
  std::vector<RayRow> failing_rays;
  BaselineMatch baseline = BaselineMatch::None;
  std::string device_name;          // the device that ran it (results bundle)
};

}  // namespace rayspec
