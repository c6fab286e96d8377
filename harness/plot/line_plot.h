// Line and scatter plots drawn by gnuplot (Debian's gnuplot-nox, which
// tools/setup.sh installs): the harness writes a gnuplot script with the data
// inline beside the image (<image>.gp, to redraw or restyle by hand) and runs
// gnuplot on it. Panels are small multiples in a grid; every legend sits
// outside its panel's data; a series' colour follows its name, the same in
// every panel.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct PlotSeries {
  std::string name;                               // picks the colour; the legend's entry
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in the order given
  std::string key;                                // the legend's entry instead of name, if set
};

struct PlotPanel {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;  // log axes leave out points <= 0
  std::vector<PlotSeries> series;
  bool lines = true;  // false: a scatter plot, markers only
  double y_max = 0;   // > 0: the y axis ends there (panels meant to be compared share it)
};

struct PlotLayout {
  int columns = 2;                            // panels per row
  int panel_width = 640, panel_height = 420;  // pixels
  std::string title;                          // above every panel, if set
};

// The gnuplot script that draws the panels, row by row, into the PNG `image`.
std::string gnuplotScript(const std::string& image, const std::vector<PlotPanel>& panels,
                          const PlotLayout& layout);

// Writes the script to <path>.gp and runs gnuplot on it, which writes the
// PNG at `path`. An error names what failed: no panel, a file that cannot be
// written, gnuplot missing, or what gnuplot printed when it failed.
Result<void> writePlots(const std::string& path, const std::vector<PlotPanel>& panels,
                        const PlotLayout& layout = {});

}  // namespace rayspec
