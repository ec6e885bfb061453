#include <gmock/gmock.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel::plot;
using ::testing::DoubleNear;
using ::testing::ElementsAre;

TEST(NiceTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_THAT(nice_ticks(0.0, 1.0),
              ElementsAre(0.0, DoubleNear(0.2, 1e-12), DoubleNear(0.4, 1e-12), DoubleNear(0.6, 1e-12),
                          DoubleNear(0.8, 1e-12), DoubleNear(1.0, 1e-12)));
  EXPECT_THAT(nice_ticks(-3.0, 17.0), ElementsAre(0.0, 5.0, 10.0, 15.0));
  EXPECT_THAT(nice_ticks(0.0, 24.0), ElementsAre(0.0, 5.0, 10.0, 15.0, 20.0));
  EXPECT_TRUE(nice_ticks(1.0, 1.0).empty());
}

TEST(SavePng, DrawsEachPanelAndItsSeries) {
  const auto file = kestrel::testing::scratch_path("kestrel-plot-test.png");
  Panel panel;
  panel.title = "line";
  Series s;
  s.color = Color{255, 0, 0};
  s.x = {0, 1, 2};
  s.y = {1, 1, 1};
  panel.series.push_back(s);
  save_png(file, {panel, panel}, 400, 200);
  const cv::Mat img = cv::imread(file.string());
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 400);
  EXPECT_EQ(img.rows, 400);
  // The constant series is a red horizontal line through the middle of each panel's plot area.
  int red = 0;
  for (int x = 0; x < img.cols; ++x) {
    const auto p = img.at<cv::Vec3b>(30 + (200 - 30 - 45) / 2, x);
    if (p[2] > 200 && p[1] < 80 && p[0] < 80) ++red;
  }
  EXPECT_GT(red, 200);
  EXPECT_THROW(save_png("/nonexistent-dir/x.png", {panel}), kestrel::Error);
}

// The legend goes to the corner with the fewest data points: a curve ending in the top-right
// corner, where the legend used to sit, stays visible.
TEST(SavePng, TheLegendDoesNotHideTheData) {
  const auto file = kestrel::testing::scratch_path("kestrel-plot-legend-test.png");
  auto blue_pixels = [&](const std::string& label) {
    Panel panel;
    Series climbing;  // unlabelled: no swatch of its colour in the legend
    climbing.color = Color{0, 0, 255};
    climbing.style = Series::Style::points;
    for (int k = 0; k <= 10; ++k) {
      climbing.x.push_back(k);
      climbing.y.push_back(k * k);
    }
    Series named;
    named.label = label;
    named.color = Color{0, 200, 0};
    named.x = {0, 10};
    named.y = {50, 50};
    panel.series = {climbing, named};
    save_png(file, {panel}, 600, 300);
    const cv::Mat img = cv::imread(file.string());
    int n = 0;
    for (int r = 0; r < img.rows; ++r)
      for (int c = 0; c < img.cols; ++c) {
        const auto p = img.at<cv::Vec3b>(r, c);
        if (p[0] > 200 && p[1] < 80 && p[2] < 80) ++n;
      }
    return n;
  };
  const int without_legend = blue_pixels("");
  EXPECT_GT(without_legend, 100);
  EXPECT_EQ(blue_pixels("a long legend label"), without_legend);
}
