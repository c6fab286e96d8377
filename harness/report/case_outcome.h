// What a run concluded about one case: the verdict, the times, and where its
// results bundles and images are, for every report.
#pragma once

#include <string>
#include <vector>

#include "base/enum_names.h"
#include "compare/verdict.h"
#include "results/step_cost.h"

namespace rayspec {

// One failing ray, device against model, for the per-ray tables of the report.
struct RayRow {
  uint32_t ray = 0, x = 0, y = 0;
  std::string field, device, model;
};

// How a case's result stands against the driver's baseline (report/baseline.h,
// judged by report/baseline_gate.h).
#define RAYSPEC_BASELINE_MATCHES(X)                                                       \
  /* no baseline, or a result it says nothing about: judged by its status alone */        \
  X(None, "")                                                                             \
  X(Expected, "expected") /* the baseline lists exactly this result */                    \
  /* the baseline expects a failure and the case no longer fails: update the baseline */  \
  X(UnexpectedPass, "unexpected_pass")                                                    \
  X(KnownFlake, "known_flake") /* an unexpected result of a case the flakes file names */ \
  X(Flake, "flake")            /* an unexpected failure that its re-run did not repeat */ \
  X(Skipped, "skipped")        /* named by the skips file: not run */
enum class BaselineMatch { RAYSPEC_BASELINE_MATCHES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(BaselineMatch, RAYSPEC_BASELINE_MATCHES);

struct CaseOutcome {
  std::string name;
  std::vector<std::string> rules;
  Status status = Status::Pass;
  std::string headline;
  double seconds = 0.0, device_seconds = 0.0, model_seconds = 0.0;
  CaseCost cost;  // where the case's time went, per side and step (<case>/cost.json)
  Verdict verdict;
  std::vector<std::string> images;  // image names; files at <case>/{device,model,diff}/<name>.png
  std::vector<RayRow> failing_rays;
  BaselineMatch baseline = BaselineMatch::None;
  std::string baseline_note;  // why: the entry, pattern (file:line) or re-run that decided it
  std::string device_name;    // the device that ran it (results bundle)

  // Takes status and headline from the verdict: the one place they are
  // derived, called after the verdict's last finding is added.
  void deriveFromVerdict() {
    status = verdict.status;
    headline = verdict.headline();
  }
};

}  // namespace rayspec
