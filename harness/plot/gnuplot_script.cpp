// The gnuplot script of a set of panels: the data as named blocks first, then
// one multiplot, one panel after another.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "plot/line_plot.h"

namespace rayspec {
namespace {

// Distinct colours, one per series name in order of first appearance.
constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
constexpr size_t kColours = sizeof kPalette / sizeof kPalette[0];

// A gnuplot string literal: single quotes take everything as written but a
// quote, which is doubled.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += '\'';
    if (c != '\n') out += c;
  }
  return out + "'";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

bool drawable(const PlotPanel& p, const std::pair<double, double>& pt) {
  const auto [x, y] = pt;
  return std::isfinite(x) && std::isfinite(y) && (!p.log_x || x > 0) && (!p.log_y || y > 0);
}

// $p<i>s<j>: series j of panel i, its drawable points one per line.
std::string blockName(size_t panel, size_t series) {
  return "$p" + std::to_string(panel) + "s" + std::to_string(series);
}

void writeDataBlocks(std::ostringstream& s, const std::vector<PlotPanel>& panels) {
  for (size_t i = 0; i < panels.size(); ++i)
    for (size_t j = 0; j < panels[i].series.size(); ++j) {
      s << blockName(i, j) << " << EOD\n";
      for (const auto& pt : panels[i].series[j].points)
        if (drawable(panels[i], pt)) s << number(pt.first) << ' ' << number(pt.second) << '\n';
      s << "EOD\n";
    }
}

// On a log x axis, a tick every decade, or every few where many decades
// would crowd a small panel.
std::string logTicks(const PlotPanel& p) {
  double lo = INFINITY, hi = -INFINITY;
  for (const PlotSeries& series : p.series)
    for (const auto& pt : series.points)
      if (drawable(p, pt)) lo = std::min(lo, pt.first), hi = std::max(hi, pt.first);
  const double decades = hi > lo ? std::log10(hi / lo) : 0;
  const int step = decades > 6 ? static_cast<int>(std::ceil(decades / 5)) : 1;
  return "set xtics " + number(std::pow(10.0, step)) + "\n";
}

void writeAxes(std::ostringstream& s, const PlotPanel& p) {
  s << "unset logscale\n";
  if (p.log_x)
    s << "set logscale x 10\nset format x '1e%T'\n" << logTicks(p);
  else
    s << "set format x '%g'\nset xtics autofreq\n";
  if (p.log_y)
    s << "set logscale y 10\nset format y '1e%T'\n";
  else
    s << "set format y '%g'\n";
  s << "set xlabel " << quoted(p.x_label) << "\nset ylabel " << quoted(p.y_label) << '\n';
  // The legend outside the data: under a line panel (its few series), right
  // of a scatter panel (a series a source, with longer names).
  if (p.lines)
    s << "set key bmargin center horizontal samplen 2\nset bmargin 5\nset rmargin 2\n";
  else
    s << "set key rmargin top vertical samplen 1\nset bmargin 3.5\nset rmargin 24\n";
  s << "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n";
  s << "set xrange [*:*]\n";
  if (p.y_max > 0)
    s << "set yrange [" << (p.log_y ? "*" : "0") << ':' << number(p.y_max) << "]\n";
  else
    s << "set yrange [" << (p.log_y ? "*" : "0") << ":*]\n";
}

// The plot command: one clause per series that has a drawable point, in its
// name's colour; a panel without any gets an empty frame that says so.
void writePlotCommand(std::ostringstream& s, const PlotPanel& p, size_t index,
                      std::map<std::string, size_t>& colours) {
  std::vector<std::string> clauses;
  for (size_t j = 0; j < p.series.size(); ++j) {
    const PlotSeries& series = p.series[j];
    const size_t colour = colours.emplace(series.name, colours.size()).first->second;
    if (std::none_of(series.points.begin(), series.points.end(),
                     [&](const auto& pt) { return drawable(p, pt); }))
      continue;
    clauses.push_back(blockName(index, j) + " using 1:2 with " +
                      (p.lines ? "linespoints pt 7 ps 0.7 lw 1.5" : "points pt 5 ps 1.2") +
                      " lc rgb '" + kPalette[colour % kColours] + "' title " +
                      quoted(series.key.empty() ? series.name : series.key));
  }
  if (clauses.empty()) {
    s << "set xrange [0:1]\nset yrange [0:1]\nunset logscale\n"
      << "set label 1 'no data' at graph 0.5, 0.5 center\nplot NaN notitle\nunset label 1\n";
    return;
  }
  s << "plot ";
  for (size_t k = 0; k < clauses.size(); ++k) s << (k ? ", \\\n     " : "") << clauses[k];
  s << '\n';
}

}  // namespace

std::string gnuplotScript(const std::string& image, const std::vector<PlotPanel>& panels,
                          const PlotLayout& layout) {
  const int columns = std::max(1, layout.columns);
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  const int title_height = layout.title.empty() ? 0 : 40;
  std::ostringstream s;
  s << "# Written by rayspec (harness/plot): gnuplot " << quoted(image) << ".gp redraws it.\n";
  writeDataBlocks(s, panels);
  s << "set terminal pngcairo noenhanced size " << columns * layout.panel_width << ','
    << rows * layout.panel_height + title_height << " font 'DejaVu Sans,10'\n"
    << "set output " << quoted(image) << '\n'
    << "set grid lc rgb '#dddddd'\nset border lc rgb '#444444'\n"

    << "set multiplot layout " << rows << ',' << columns;
  if (!layout.title.empty()) s << " title " << quoted(layout.title) << " font ',13'";
  s << '\n';
  std::map<std::string, size_t> colours;
  for (size_t i = 0; i < panels.size(); ++i) {
    s << "# panel " << i + 1 << "\nset title " << quoted(panels[i].title) << " font ',11'\n";
    writeAxes(s, panels[i]);
    writePlotCommand(s, panels[i], i, colours);
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace rayspec
