#include <gmock/gmock.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "kestrel/error.hpp"
#include "kestrel/plot/line_plot.hpp"

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
  const auto file = std::filesystem::temp_directory_path() / "kestrel-plot-test.png";
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
