// Line plots (plot/line_plot.h): axis ticks and a written image.
#include <gtest/gtest.h>

#include <filesystem>

#include "plot/line_plot.h"

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imagebuf.h>
#endif

namespace rayspec {
namespace {

TEST(AxisTicks, LogDecadesCoverTheData) {
  const AxisTicks a = axisTicks(1, 1e6, true);
  EXPECT_EQ(a.lo, 1);
  EXPECT_EQ(a.hi, 1e6);
  EXPECT_EQ(a.ticks.size(), 7u);
  const AxisTicks b = axisTicks(3e-4, 20, true);
  EXPECT_DOUBLE_EQ(b.lo, 1e-4);
  EXPECT_DOUBLE_EQ(b.hi, 100);
  const AxisTicks one = axisTicks(10, 10, true);
  EXPECT_LT(one.lo, one.hi);
}

TEST(AxisTicks, LinearRoundSteps) {
  const AxisTicks a = axisTicks(0, 7.3, false);
  EXPECT_EQ(a.lo, 0);
  EXPECT_GE(a.hi, 7.3);
  ASSERT_GE(a.ticks.size(), 2u);
  EXPECT_DOUBLE_EQ(a.ticks[1] - a.ticks[0], 2);
  const AxisTicks zero = axisTicks(0, 0, false);  // all-zero data still gets an axis
  EXPECT_EQ(zero.lo, 0);
  EXPECT_EQ(zero.hi, 1);
}

#ifdef RAYSPEC_WITH_OIIO
TEST(LinePlot, WritesAnImageWithLinesInTheSeriesColours) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "rayspec-plot-test.png").string();
  PlotPanel p{"rates",         "magnitude",
              "per 1000 rays", true,
              false,           {{"a", {{1, 0}, {10, 5}, {100, 10}}}, {"b", {{1, 10}, {100, 0}}}}};
  ASSERT_EQ(writeLinePlots(path, {p, p}, {2, 400, 300}), "");
  OIIO::ImageBuf img(path);
  ASSERT_TRUE(img.read());
  EXPECT_EQ(img.spec().width, 800);
  EXPECT_EQ(img.spec().height, 300);
  // Some pixels carry series a's blue, some series b's red.
  int blue = 0, red = 0;
  float px[3];
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 800; ++x) {
      img.getpixel(x, y, px, 3);
      blue += px[2] > 0.6f && px[0] < 0.2f;
      red += px[0] > 0.75f && px[1] < 0.25f;
    }
  EXPECT_GT(blue, 100);
  EXPECT_GT(red, 100);
  EXPECT_NE(writeLinePlots("/nonexistent-dir/x.png", {p}), "");
  EXPECT_NE(writeLinePlots(path, {}), "");
}

// Blue pixels (series a's colour) of the plot.
int bluePixels(const std::string& path) {
  OIIO::ImageBuf img(path);
  if (!img.read()) return -1;
  int blue = 0;
  float px[3];
  for (int y = 0; y < img.spec().height; ++y)
    for (int x = 0; x < img.spec().width; ++x) {
      img.getpixel(x, y, px, 3);
      blue += px[2] > 0.6f && px[0] < 0.2f;
    }
  return blue;
}

TEST(LinePlot, ScatterPanelsDrawMarkersOnlyAndLabelThePoints) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "rayspec-scatter-test.png").string();
  PlotPanel p{"scatter", "ms", "rate",
              true,      true, {{"a", {{1, 1}, {1000, 1000}}, {"first", "second"}}}};
  ASSERT_EQ(writeLinePlots(path, {p}, {1, 400, 300}), "");
  const int with_lines = bluePixels(path);
  p.lines = false;
  ASSERT_EQ(writeLinePlots(path, {p}, {1, 400, 300}), "");
  const int markers = bluePixels(path);
  EXPECT_GT(markers, 100);  // two 11x11 markers and the legend's box
  EXPECT_LT(markers, with_lines - 300) << "no line joins the points";
  // The labels are black text beside the markers: more dark pixels than without them.
  auto dark = [&] {
    OIIO::ImageBuf img(path);
    img.read();
    int n = 0;
    float px[3];
    for (int y = 0; y < 300; ++y)
      for (int x = 0; x < 400; ++x) {
        img.getpixel(x, y, px, 3);
        n += px[0] < 0.3f && px[1] < 0.3f && px[2] < 0.3f;
      }
    return n;
  };
  const int labelled = dark();
  p.series[0].labels.clear();
  ASSERT_EQ(writeLinePlots(path, {p}, {1, 400, 300}), "");
  EXPECT_GT(labelled, dark() + 20);
}
#endif

}  // namespace
}  // namespace rayspec
