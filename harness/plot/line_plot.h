// Line and scatter plots written as an image (PNG by the file's extension)
// with OpenImageIO: one or more panels, each with its axes (linear or log),
// labels, a title and a legend; per series its markers, joined by a line
// unless the panel is a scatter plot, each with its own label if given.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rayspec {

struct PlotSeries {
  std::string name;                               // the legend's entry
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in the order given
  std::vector<std::string> labels;                // optional: text beside each point (same order)
};

struct PlotPanel {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;  // log axes leave out points <= 0
  std::vector<PlotSeries> series;     // a series' colour follows its name, the same in every panel
  bool lines = true;                  // false: a scatter plot, markers only
};

struct PlotLayout {
  int columns = 2;                            // panels per row
  int panel_width = 640, panel_height = 420;  // pixels
};

// Writes the panels, row by row, into one image at `path`. Returns "" or
// what went wrong (no panel, a file that cannot be written, a build without
// OpenImageIO).
std::string writeLinePlots(const std::string& path, const std::vector<PlotPanel>& panels,
                           const PlotLayout& layout = {});

// The axis range and its tick values: decades on a log axis (10^k), about
// five round steps on a linear one (1, 2 or 5 times a power of ten), always
// including the data's range; a range of one value is widened.
struct AxisTicks {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
};
AxisTicks axisTicks(double min, double max, bool log);

}  // namespace rayspec
