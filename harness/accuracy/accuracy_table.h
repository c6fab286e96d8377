// The accuracy report's rows: per case set (ordinary, hard) and source (a
// model tier or a device), the rays, their trace time and the disagreements
// with the model's exact tier; as a table, JSON and a scatter plot.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy/ray_disagreements.h"
#include "base/enum_names.h"
#include "plot/line_plot.h"

namespace rayspec {

#define RAYSPEC_CASE_SETS(X) X(Ordinary, "ordinary") X(Hard, "hard")
enum class CaseSet { RAYSPEC_CASE_SETS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(CaseSet, RAYSPEC_CASE_SETS);
const char* caseSetName(CaseSet s);  // "ordinary", "hard"

#define RAYSPEC_SOURCE_KINDS(X) X(ModelTier, "model") X(Device, "device")
enum class SourceKind { RAYSPEC_SOURCE_KINDS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(SourceKind, RAYSPEC_SOURCE_KINDS);
const char* sourceKindName(SourceKind k);  // "model", "device"

struct AccuracyRow {
  CaseSet set = CaseSet::Ordinary;
  std::string source;  // "model fast", "llvmpipe", ...
  SourceKind kind = SourceKind::ModelTier;
  uint64_t cases = 0;
  uint64_t launch_rays = 0;  // width * height of each case's launch, summed
  double trace_seconds = 0;  // model_trace (model) or trace (device), summed
  Disagreements d;
  // Milliseconds of trace per million launch rays (0 without rays).
  double msPerMray() const { return launch_rays ? trace_seconds * 1e3 / (launch_rays / 1e6) : 0; }
};

// Adds one case's figures to the (set, source) row, keeping first-appearance order.
void addToRow(std::vector<AccuracyRow>& rows, const AccuracyRow& one);

// One table per set: source, cases, rays, ms/Mray, disagreeing rays per
// million, leaks, double hits, other primitive, extra hits, t error median,
// p99 and max in ULP; then each row's t error histogram.
std::string formatAccuracyTable(const std::vector<AccuracyRow>& rows);
nlohmann::json accuracyJson(const std::vector<AccuracyRow>& rows);
// One panel per set: disagreeing rays per million against ms per Mray, log
// axes, one labelled point per source (no disagreement drawn at the floor,
// 0.1 per million, and labelled so).
std::vector<PlotPanel> accuracyPanels(const std::vector<AccuracyRow>& rows);
inline constexpr double kPlotFloorPerMillion = 0.1;

}  // namespace rayspec
