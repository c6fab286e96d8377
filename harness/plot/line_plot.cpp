// Line and scatter plots drawn with OpenImageIO's ImageBufAlgo (lines, boxes, text).
#include "plot/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#endif

namespace rayspec {

#ifdef RAYSPEC_WITH_OIIO
namespace {

namespace IBA = OIIO::ImageBufAlgo;

// Distinct colours (RGB), one per series name in order of first appearance.
constexpr float kPalette[][3] = {
    {0.12f, 0.47f, 0.71f}, {0.84f, 0.15f, 0.16f}, {0.17f, 0.63f, 0.17f}, {1.00f, 0.50f, 0.05f},
    {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f}, {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f},
    {0.74f, 0.74f, 0.13f}, {0.09f, 0.75f, 0.81f}};
constexpr float kBlack[3] = {0, 0, 0}, kGrey[3] = {0.85f, 0.85f, 0.85f};

std::string fontPath() {
  for (const char* f :
       {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
    if (std::filesystem::exists(f)) return f;
  return "";  // OpenImageIO's own search
}

std::string tickLabel(double v, bool log) {
  char buf[32];
  if (log) {
    const int e = static_cast<int>(std::lround(std::log10(v)));
    if (e == 0) return "1";
    std::snprintf(buf, sizeof buf, "1e%d", e);
  } else {
    std::snprintf(buf, sizeof buf, "%g", v);
  }
  return buf;
}

struct Frame {
  int x0, y0, x1, y1;  // plot area in pixels (y0 top)
  AxisTicks x, y;
  bool log_x, log_y;
  int px(double v) const {
    const double t =
        log_x ? (std::log10(v) - std::log10(x.lo)) / (std::log10(x.hi) - std::log10(x.lo))
              : (v - x.lo) / (x.hi - x.lo);
    return x0 + static_cast<int>(std::lround(t * (x1 - x0)));
  }
  int py(double v) const {
    const double t =
        log_y ? (std::log10(v) - std::log10(y.lo)) / (std::log10(y.hi) - std::log10(y.lo))
              : (v - y.lo) / (y.hi - y.lo);
    return y1 - static_cast<int>(std::lround(t * (y1 - y0)));
  }
};

bool usable(const PlotPanel& p, const std::pair<double, double>& pt) {
  return std::isfinite(pt.first) && std::isfinite(pt.second) && (!p.log_x || pt.first > 0) &&
         (!p.log_y || pt.second > 0);
}

void drawPanel(OIIO::ImageBuf& img, int ox, int oy, const PlotLayout& lay, const PlotPanel& p,
               const std::map<std::string, size_t>& colour_of, const std::string& font) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const PlotSeries& s : p.series)
    for (const auto& pt : s.points) {
      if (!usable(p, pt)) continue;
      xmin = std::min(xmin, pt.first);
      xmax = std::max(xmax, pt.first);
      ymin = std::min(ymin, pt.second);
      ymax = std::max(ymax, pt.second);
    }
  if (!p.log_y && ymin > 0) ymin = 0;  // rates and counts start at zero
  Frame f{ox + 70,
          oy + 34,
          ox + lay.panel_width - 20,
          oy + lay.panel_height - 56,
          axisTicks(xmin, xmax, p.log_x),
          axisTicks(ymin, ymax, p.log_y),
          p.log_x,
          p.log_y};
  auto text = [&](int x, int y, const std::string& s, int size, IBA::TextAlignX ax,
                  IBA::TextAlignY ay) {
    IBA::render_text(img, x, y, s, size, font, kBlack, ax, ay);
  };
  for (double t : f.x.ticks) {
    IBA::render_line(img, f.px(t), f.y0, f.px(t), f.y1, kGrey);
    text(f.px(t), f.y1 + 6, tickLabel(t, p.log_x), 13, IBA::TextAlignX::Center,
         IBA::TextAlignY::Top);
  }
  for (double t : f.y.ticks) {
    IBA::render_line(img, f.x0, f.py(t), f.x1, f.py(t), kGrey);
    text(f.x0 - 6, f.py(t), tickLabel(t, p.log_y), 13, IBA::TextAlignX::Right,
         IBA::TextAlignY::Center);
  }
  IBA::render_box(img, f.x0, f.y0, f.x1, f.y1, kBlack);
  text((f.x0 + f.x1) / 2, oy + 8, p.title, 16, IBA::TextAlignX::Center, IBA::TextAlignY::Top);
  text((f.x0 + f.x1) / 2, f.y1 + 28, p.x_label, 14, IBA::TextAlignX::Center, IBA::TextAlignY::Top);
  text(ox + 6, oy + 20, p.y_label, 13, IBA::TextAlignX::Left, IBA::TextAlignY::Center);
  int legend_y = f.y0 + 10;
  for (size_t j = 0; j < p.series.size(); ++j) {
    const PlotSeries& s = p.series[j];
    const float* c = kPalette[colour_of.at(s.name) % std::size(kPalette)];
    bool first = true;
    int lx = 0, ly = 0;
    for (size_t i = 0; i < s.points.size(); ++i) {
      const auto& pt = s.points[i];
      if (!usable(p, pt)) continue;
      const int x = f.px(pt.first), y = f.py(pt.second);
      if (i < s.labels.size() && !s.labels[i].empty()) {
        // Beside the point, towards the middle of the plot so the text stays
        // inside, each series a line higher than the one before (cycling
        // through four) so the labels of nearby points do not overlap.
        const int lift = 8 + 15 * static_cast<int>(j % 4);
        text(x < (f.x0 + f.x1) / 2 ? x + 8 : x - 8, y < f.y0 + lift + 16 ? y + lift + 8 : y - lift,
             s.labels[i], 13,
             x < (f.x0 + f.x1) / 2 ? IBA::TextAlignX::Left : IBA::TextAlignX::Right,
             IBA::TextAlignY::Bottom);
      }
      if (!first && p.lines) {
        IBA::render_line(img, lx, ly, x, y, {c, 3}, true);
        IBA::render_line(img, lx, ly + 1, x, y + 1, {c, 3}, true);
      }
      const int r = p.lines ? 3 : 5;  // a scatter plot's markers stand alone: larger
      IBA::render_box(img, x - r, y - r, x + r, y + r, {c, 3}, true);
      lx = x;
      ly = y;
      first = false;
    }
    // Legend entry, top right inside the plot area.
    IBA::render_box(img, f.x1 - 190, legend_y - 4, f.x1 - 176, legend_y + 4, {c, 3}, true);
    text(f.x1 - 170, legend_y, s.name, 13, IBA::TextAlignX::Left, IBA::TextAlignY::Center);
    legend_y += 18;
  }
}

}  // namespace

std::string writeLinePlots(const std::string& path, const std::vector<PlotPanel>& panels,
                           const PlotLayout& lay) {
  if (panels.empty()) return "no panel to plot";
  const int cols = std::max(1, std::min<int>(lay.columns, static_cast<int>(panels.size())));
  const int rows = (static_cast<int>(panels.size()) + cols - 1) / cols;
  OIIO::ImageSpec spec(cols * lay.panel_width, rows * lay.panel_height, 3, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf img(spec);
  const float white[3] = {1, 1, 1};
  IBA::fill(img, white);
  std::map<std::string, size_t> colour_of;
  for (const PlotPanel& p : panels)
    for (const PlotSeries& s : p.series) colour_of.emplace(s.name, colour_of.size());
  const std::string font = fontPath();
  for (size_t i = 0; i < panels.size(); ++i)
    drawPanel(img, static_cast<int>(i % cols) * lay.panel_width,
              static_cast<int>(i / cols) * lay.panel_height, lay, panels[i], colour_of, font);
  if (!img.write(path)) return path + ": " + img.geterror();
  return "";
}

#else

std::string writeLinePlots(const std::string& path, const std::vector<PlotPanel>&,
                           const PlotLayout&) {
  return path + ": this build has no OpenImageIO (RAYSPEC_WITH_OIIO=OFF), so no plot";
}

#endif

}  // namespace rayspec
