// Poisson false alarms (clutter), as false_alarms draws them.
#include <gmock/gmock.h>

#include "false_alarm_model.hpp"
#include "kestrel/error.hpp"

using namespace kestrel::scenario;

TEST(FalseAlarmModel, PoissonCountsInsideTheBox) {
  FalseAlarmBox box{{-1, -2, 3}, {1, 2, 4}};
  FalseAlarmModel model(0.5, box);
  std::mt19937_64 rng(7);
  const int frames = 20000;
  std::vector<int> counts;
  double sum = 0, sum_sq = 0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int points = 0;
  for (int k = 0; k < frames; ++k) {
    const auto alarms = model.draw(rng);
    sum += static_cast<double>(alarms.size());
    sum_sq += static_cast<double>(alarms.size() * alarms.size());
    for (const auto& p : alarms) {
      EXPECT_TRUE((p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all()) << p.transpose();
      mean += p;
      ++points;
    }
  }
  // A Poisson count: mean and variance both 0.5 (standard error of the mean 0.005).
  const double m = sum / frames;
  EXPECT_NEAR(m, 0.5, 0.025);
  EXPECT_NEAR(sum_sq / frames - m * m, 0.5, 0.05);
  // Uniform in the box: the mean point is its centre.
  mean /= points;
  EXPECT_NEAR(mean.x(), 0.0, 0.03);
  EXPECT_NEAR(mean.y(), 0.0, 0.06);
  EXPECT_NEAR(mean.z(), 3.5, 0.015);
}

TEST(FalseAlarmModel, SameSeedSameClutterAndBadSettingsAreRefused) {
  FalseAlarmModel model(2.0, FalseAlarmBox{});
  std::mt19937_64 a(3), b(3);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(model.draw(a), model.draw(b));
  std::mt19937_64 rng(1);
  EXPECT_TRUE(FalseAlarmModel(0.0, FalseAlarmBox{}).draw(rng).empty());
  EXPECT_THROW(FalseAlarmModel(-1.0, FalseAlarmBox{}), kestrel::Error);
  EXPECT_THROW(FalseAlarmModel(1.0, FalseAlarmBox{{0, 0, 5}, {1, 1, 4}}), kestrel::Error);
}
