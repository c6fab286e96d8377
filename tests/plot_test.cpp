// Plots (plot/line_plot.h): the gnuplot script, and the image gnuplot draws
// from it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "plot/line_plot.h"

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imagebuf.h>
#endif

namespace rayspec {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

PlotPanel rates() {
  PlotPanel p;
  p.title = "rates";
  p.x_label = "magnitude";
  p.y_label = "per 1000 rays";
  p.log_x = true;
  p.series = {{"a", {{1, 0}, {10, 5}, {100, 10}}}, {"b", {{1, 10}, {100, 0}}}};
  return p;
}

TEST(GnuplotScript, OnePanelPerPanelColoursByNameLegendOutside) {
  PlotPanel second = rates();
  std::swap(second.series[0], second.series[1]);  // b first: it keeps its colour
  const std::string s = gnuplotScript("/tmp/x.png", {rates(), second}, {2, 400, 300, "Both"});
  EXPECT_NE(s.find("set terminal pngcairo noenhanced size 800,340"), std::string::npos) << s;
  EXPECT_NE(s.find("set multiplot layout 1,2 title 'Both'"), std::string::npos) << s;
  EXPECT_EQ(count(s, "\nplot "), 2u) << s;
  EXPECT_EQ(count(s, "lc rgb '#1f77b4' title 'a'"), 2u) << s;  // a: the first colour in both
  EXPECT_EQ(count(s, "lc rgb '#d62728' title 'b'"), 2u) << s;
  EXPECT_NE(s.find("set key bmargin"), std::string::npos) << "the legend sits below the axes";
  EXPECT_NE(s.find("set logscale x 10"), std::string::npos);
  EXPECT_NE(s.find("linespoints"), std::string::npos);
}

TEST(GnuplotScript, LogAxesDropPointsAtOrBelowZeroAndQuotesAreDoubled) {
  PlotPanel p = rates();
  p.log_y = true;
  p.lines = false;
  p.title = "it's";
  const std::string s = gnuplotScript("/tmp/x.png", {p}, {});
  EXPECT_NE(s.find("$p0s0 << EOD\n10 5\n100 10\nEOD\n"), std::string::npos) << s;
  EXPECT_NE(s.find("$p0s1 << EOD\n1 10\nEOD\n"), std::string::npos) << s;
  EXPECT_NE(s.find("set title 'it''s'"), std::string::npos) << s;
  EXPECT_NE(s.find("with points"), std::string::npos);
  EXPECT_EQ(s.find("linespoints"), std::string::npos);
}

TEST(GnuplotScript, SharedYAxisKeysAndAnEmptyPanel) {
  PlotPanel p = rates();
  p.y_max = 12;
  p.series[1].key = "b (0)";
  PlotPanel empty;
  empty.title = "nothing";
  empty.series = {{"a", {}}};
  const std::string s = gnuplotScript("/tmp/x.png", {p, empty}, {});
  EXPECT_NE(s.find("set yrange [0:12]"), std::string::npos) << s;
  EXPECT_NE(s.find("title 'b (0)'"), std::string::npos) << s;
  EXPECT_NE(s.find("'no data'"), std::string::npos) << s;
}

TEST(WritePlots, ErrorsNameWhatFailed) {
  const Result<void> none = writePlots("/tmp/rayspec-plot-none.png", {});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("no panel"), std::string::npos);
  const Result<void> nowhere = writePlots("/nonexistent-dir/x.png", {rates()});
  ASSERT_FALSE(nowhere);
  EXPECT_NE(nowhere.error().message.find("/nonexistent-dir/x.png"), std::string::npos);
}

#ifdef RAYSPEC_WITH_OIIO
// Pixels of a colour (within a small distance) in the image.
int pixelsOf(const OIIO::ImageBuf& img, float r, float g, float b) {
  int n = 0;
  float px[4];
  for (int y = 0; y < img.spec().height; ++y)
    for (int x = 0; x < img.spec().width; ++x) {
      img.getpixel(x, y, px, 3);
      n +=
          std::abs(px[0] - r) < 0.08f && std::abs(px[1] - g) < 0.08f && std::abs(px[2] - b) < 0.08f;
    }
  return n;
}

TEST(WritePlots, GnuplotDrawsTheSeriesInTheirColours) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "rayspec-plot-test.png").string();
  const Result<void> r = writePlots(path, {rates(), rates()}, {2, 400, 300});
  ASSERT_TRUE(r) << r.error().format();
  EXPECT_TRUE(std::filesystem::exists(path + ".gp")) << "the script stays beside the image";
  OIIO::ImageBuf img(path);
  ASSERT_TRUE(img.read());
  EXPECT_EQ(img.spec().width, 800);
  EXPECT_EQ(img.spec().height, 300);
  const int blue = pixelsOf(img, 0x1f / 255.f, 0x77 / 255.f, 0xb4 / 255.f);
  const int red = pixelsOf(img, 0xd6 / 255.f, 0x27 / 255.f, 0x28 / 255.f);
  EXPECT_GT(blue, 100);
  EXPECT_GT(red, 100);
  // Without series b, no red is drawn.
  PlotPanel only_a = rates();
  only_a.series.pop_back();
  const std::string path_a = path + "-a.png";  // not the same name: OpenImageIO caches images
  ASSERT_TRUE(writePlots(path_a, {only_a}, {1, 400, 300}));
  OIIO::ImageBuf again(path_a);
  ASSERT_TRUE(again.read());
  EXPECT_LT(pixelsOf(again, 0xd6 / 255.f, 0x27 / 255.f, 0x28 / 255.f), 5);
}
#endif

}  // namespace
}  // namespace rayspec
