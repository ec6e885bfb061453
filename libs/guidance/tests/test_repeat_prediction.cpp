// A target that repeats its own past: analogues found where it flew before, the paths they give,
// and the weight the sightings lend them.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/guidance/repeat_prediction.hpp>
#include <kestrel/guidance/target_futures.hpp>

using namespace kestrel::guidance;

namespace {

constexpr double kDt = 1.0 / 30.0;

RepeatConfig on() {
  RepeatConfig c;
  c.prior = 0.5;
  return c;
}

// A circle of radius 2 m, once every 4 s, at 3 m height.
Eigen::Vector3d circle(double t) {
  const double w = 2.0 * M_PI / 4.0;
  return {2.0 * std::cos(w * t), 2.0 * std::sin(w * t), 3.0};
}
Eigen::Vector3d circle_velocity(double t) {
  const double w = 2.0 * M_PI / 4.0;
  return {-2.0 * w * std::sin(w * t), 2.0 * w * std::cos(w * t), 0.0};
}

}  // namespace

TEST(RepeatPrediction, ATargetThatCirclesIsForeseenFromItsLastLaps) {
  RepeatPredictor repeat(on());
  double t = 0.0;
  for (; t < 12.0; t += kDt) repeat.observe(kDt, circle(t), circle_velocity(t));
  const auto paths = repeat.paths(30, 0.1, Eigen::Vector3d::Zero());
  ASSERT_GE(paths.size(), 2u);  // a lap ago, two laps ago
  for (const auto& path : paths) {
    EXPECT_LT((path.col(10) - circle(t - kDt + 1.0)).norm(), 0.15);  // a second ahead, round the circle
    EXPECT_LT((path.col(30) - circle(t - kDt + 3.0)).norm(), 0.15);
  }
}

TEST(RepeatPrediction, ATargetThatNeverComesBackHasNoAnalogue) {
  RepeatPredictor repeat(on());
  for (double t = 0.0; t < 12.0; t += kDt) repeat.observe(kDt, {2.0 * t, 0.0, 3.0}, {2.0, 0.0, 0.0});
  EXPECT_TRUE(repeat.paths(30, 0.1, Eigen::Vector3d::Zero()).empty());
  RepeatPredictor off(RepeatConfig{.prior = 0.0});  // no hypothesis
  for (double t = 0.0; t < 12.0; t += kDt) off.observe(kDt, circle(t), circle_velocity(t));
  EXPECT_TRUE(off.paths(30, 0.1, Eigen::Vector3d::Zero()).empty());
  EXPECT_EQ(off.probability(), 0.0);
}

TEST(RepeatPrediction, ItsWeightRisesWhenItForetellsBetterThanTheModels) {
  RepeatPredictor repeat(on());
  for (double t = 0.0; t < 20.0; t += kDt) {
    repeat.observe(kDt, circle(t), circle_velocity(t));
    // The models foretell a straight flight at the present velocity; the circle bends away from it.
    repeat.paths(30, 0.1, circle(t) + circle_velocity(t) * 1.0);
  }
  EXPECT_GT(repeat.probability(), 0.85);
  // Where the models foretell the circle as well as the analogues, nothing is learnt either way.
  RepeatPredictor even(on());
  for (double t = 0.0; t < 20.0; t += kDt) {
    even.observe(kDt, circle(t), circle_velocity(t));
    even.paths(30, 0.1, circle(t + 1.0));
  }
  EXPECT_NEAR(even.probability(), 0.5, 0.1);
}

TEST(RepeatPrediction, ThePredictorGivesTheAnaloguesTheirShareOfThePaths) {
  FuturesConfig config;
  config.samples = 16;
  config.q_velocity = config.q_acceleration = config.q_turn = 0.0;
  config.repeat = on();  // weight 0.5: half the paths
  ImmSamples predictor(config, 1);
  double t = 0.0;
  for (; t < 12.0; t += kDt) {
    tracking::State x = tracking::State::Zero();
    x.head<3>() = circle(t);
    x.segment<3>(3) = circle_velocity(t);
    predictor.observe(kDt, x, Eigen::Vector3d(20.0, 0.0, 3.0));
  }
  MotionHypothesis straight;  // the models know only the present velocity
  straight.model = tracking::MotionModel::constant_velocity;
  straight.mean.head<3>() = circle(t - kDt);
  straight.mean.segment<3>(3) = circle_velocity(t - kDt);
  straight.covariance = tracking::Covariance::Zero();
  const TargetFutures futures = predictor.predict({straight});
  ASSERT_EQ(futures.size(), 16u);
  int round_the_circle = 0;
  for (std::size_t i = 0; i < futures.size(); ++i)
    round_the_circle += (futures.position(i, 1.0) - circle(t - kDt + 1.0)).norm() < 0.15;
  EXPECT_EQ(round_the_circle, 8);
  EXPECT_NEAR(*predictor.repeating(), 0.5, 1e-12);
}
