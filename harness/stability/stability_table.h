// The stability report's numbers: leak and double-hit counts per family,
// coordinate magnitude and source (a device, or a model tier), and their
// table, JSON and plot.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/line_plot.h"
#include "stability/leak_counts.h"

namespace rayspec {

struct StabilityEntry {
  std::string family;          // the sweep's stem: stability/<family>/<variant>
  double magnitude = 0;        // the variant's `magnitude` parameter
  std::string magnitude_text;  // as the sweep writes it
  std::string source;          // "lavapipe", "model exact", ...
  LeakCounts counts;           // summed over the family's variants at this magnitude
};

// A device's column: its short name and its driver's version where the
// bundle names the driver ("llvmpipe Mesa 25.0.7"), else the whole device
// name ("llvmpipe (LLVM 15.0.6, 256 bits)"), so that two drivers of one
// device name (two lavapipe versions) keep columns of their own.
std::string stabilityDeviceSource(const std::string& device, const std::string& driver);

// Adds one case run's counts to its (family, magnitude, source) entry,
// keeping the order of first appearance.
void addCounts(std::vector<StabilityEntry>& entries, const StabilityEntry& e);

// The sources in order of first appearance.
std::vector<std::string> stabilitySources(const std::vector<StabilityEntry>& entries);

// One row per family and magnitude (families in order, magnitudes
// ascending), the rays, then each source's leak and double-hit rates per
// 1000 rays.
std::string formatStabilityTable(const std::vector<StabilityEntry>& entries);
nlohmann::json stabilityJson(const std::vector<StabilityEntry>& entries);
// One panel per family: rate per 1000 rays against magnitude (log x), a
// line per source and kind (leaks, double hits).
std::vector<PlotPanel> stabilityPanels(const std::vector<StabilityEntry>& entries);

}  // namespace rayspec
