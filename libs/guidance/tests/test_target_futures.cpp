// The target's sampled futures, and the capture chance counted on them.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/guidance/capture_chance.hpp>
#include <kestrel/guidance/target_futures.hpp>

using namespace kestrel;
using namespace kestrel::guidance;

namespace {

MotionHypothesis moving(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double probability = 1.0,
                        tracking::MotionModel model = tracking::MotionModel::constant_velocity) {
  MotionHypothesis h;
  h.model = model;
  h.mean.head<3>() = p;
  h.mean.segment<3>(3) = v;
  h.covariance = tracking::Covariance::Zero();
  h.probability = probability;
  return h;
}

FuturesConfig quiet(std::int64_t samples) {
  FuturesConfig c;
  c.samples = samples;
  c.q_velocity = c.q_acceleration = c.q_turn = 0.0;
  return c;
}

}  // namespace

TEST(TargetFutures, WithoutNoiseEveryPathIsTheModelsOwnMotion) {
  ImmSamples predictor(quiet(8), 1);
  const auto futures = predictor.predict({moving({5.0, 0.0, 2.0}, {0.0, 2.0, 0.0})});
  ASSERT_EQ(futures.size(), 8u);
  EXPECT_NEAR(futures.horizon_s(), 3.0, 1e-9);
  for (std::size_t i = 0; i < futures.size(); ++i) {
    EXPECT_TRUE(futures.position(i, 1.5).isApprox(Eigen::Vector3d(5.0, 3.0, 2.0), 1e-9));
    EXPECT_TRUE(futures.position(i, 10.0).isApprox(Eigen::Vector3d(5.0, 6.0, 2.0), 1e-9));  // held past the end
  }
  EXPECT_TRUE(futures.mean_velocity(1.0).isApprox(Eigen::Vector3d(0.0, 2.0, 0.0), 1e-9));
}

TEST(TargetFutures, EachModelGivesPathsByItsProbability) {
  ImmSamples predictor(quiet(8), 1);
  // Three quarters of the paths fly +x, a quarter -x.
  const auto futures = predictor.predict(
      {moving({0.0, 0.0, 2.0}, {1.0, 0.0, 0.0}, 0.75), moving({0.0, 0.0, 2.0}, {-1.0, 0.0, 0.0}, 0.25)});
  ASSERT_EQ(futures.size(), 8u);
  int forward = 0;
  for (std::size_t i = 0; i < futures.size(); ++i) forward += futures.position(i, 1.0).x() > 0.0;
  EXPECT_EQ(forward, 6);
  EXPECT_NEAR(futures.mean(1.0).x(), 0.5, 1e-9);
}

TEST(TargetFutures, TheManoeuvreNoiseSpreadsThePathsAsItsModelSays) {
  FuturesConfig config = quiet(4000);
  config.q_velocity = 3.0;  // white-noise acceleration: position variance q t^3 / 3
  ImmSamples predictor(config, 2);
  const auto futures = predictor.predict({moving({0.0, 0.0, 5.0}, Eigen::Vector3d::Zero())});
  for (double t : {1.0, 2.0}) {
    double sum = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < futures.size(); ++i) {
      const double x = futures.position(i, t).x();
      sum += x;
      squares += x * x;
    }
    const double n = static_cast<double>(futures.size());
    const double variance = squares / n - (sum / n) * (sum / n);
    EXPECT_NEAR(variance, 3.0 * t * t * t / 3.0, 0.1 * 3.0 * t * t * t / 3.0) << "t = " << t;
  }
}

TEST(TargetFutures, NoPathFliesFasterThanTheLimit) {
  FuturesConfig config = quiet(200);
  config.q_acceleration = 5000.0;
  config.max_speed_m_s = 6.0;
  ImmSamples predictor(config, 3);
  const auto futures =
      predictor.predict({moving({0.0, 0.0, 5.0}, {5.0, 0.0, 0.0}, 1.0, tracking::MotionModel::constant_acceleration)});
  for (std::size_t i = 0; i < futures.size(); ++i)
    for (double t = 0.0; t + 0.1 <= futures.horizon_s(); t += 0.1)
      EXPECT_LE((futures.position(i, t + 0.1) - futures.position(i, t)).norm(), 6.0 * 0.1 + 1e-9);
}

TEST(TargetFutures, TheSameSeedDrawsTheSamePaths) {
  FuturesConfig config;
  config.samples = 16;
  ImmSamples a(config, 9), b(config, 9);
  const auto h = moving({1.0, 2.0, 3.0}, {1.0, 0.0, 0.0}, 1.0, tracking::MotionModel::coordinated_turn);
  const auto fa = a.predict({h}), fb = b.predict({h});
  for (std::size_t i = 0; i < fa.size(); ++i) EXPECT_EQ(fa.paths[i], fb.paths[i]);
}

namespace {
// A level launcher at the origin facing +x; the net opens 2 m ahead and 1 m below it after 0.4 s.
const net::NetModel kNet{net::NetParams{{0.0, 1.0, 2.0}, 0.4, 0.6, 0.3}};
Launch level_launch() {
  return Launch{0.0, geometry::level_camera(Eigen::Vector3d(0.0, 0.0, 3.0), 0.0), Eigen::Vector3d::Zero()};
}
}  // namespace

TEST(CaptureChance, ATargetWhereTheNetOpensIsHeldAndOneTwoMetresOffIsNot) {
  ImmSamples predictor(quiet(10), 1);
  const auto on = predictor.predict({moving({2.0, 0.0, 2.0}, Eigen::Vector3d::Zero())});
  EXPECT_DOUBLE_EQ(capture_chance(on, kNet, level_launch()).probability, 1.0);
  const auto off = predictor.predict({moving({2.0, 2.0, 2.0}, Eigen::Vector3d::Zero())});
  const CaptureChance missed = capture_chance(off, kNet, level_launch());
  EXPECT_DOUBLE_EQ(missed.probability, 0.0);
  EXPECT_GT(missed.closeness, 0.0);
  EXPECT_LT(missed.closeness, capture_chance(on, kNet, level_launch()).closeness);
}

TEST(CaptureChance, IsTheShareOfPathsTheOpenNetHolds) {
  ImmSamples predictor(quiet(8), 1);
  // Half the paths wait where the net opens; half fly away at 5 m/s.
  const auto futures = predictor.predict(
      {moving({2.0, 0.0, 2.0}, Eigen::Vector3d::Zero(), 0.5), moving({2.0, 0.0, 2.0}, {0.0, 5.0, 0.0}, 0.5)});
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, level_launch()).probability, 0.5);
  // A launcher error of 1 m on every path loses them all.
  const std::vector<Eigen::Vector3d> errors(8, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, level_launch(), errors).probability, 0.0);
}

TEST(CaptureChance, TheNetInheritsTheLaunchersVelocity) {
  ImmSamples predictor(quiet(4), 1);
  // The target 5 m ahead: a launcher moving at 7.5 m/s towards it opens the net 3 m further on.
  const auto futures = predictor.predict({moving({5.0, 0.0, 2.0}, Eigen::Vector3d::Zero())});
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, level_launch()).probability, 0.0);
  Launch moving_launch = level_launch();
  moving_launch.velocity = Eigen::Vector3d(7.5, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, moving_launch).probability, 1.0);
}

TEST(CaptureChance, ALaunchAimedWhenItIsMadeSeesEachPathWhereItIsThen) {
  ImmSamples predictor(quiet(8), 1);
  // Half the paths hover 1 m to one side of where the net opens, half 1 m to the other: a launch
  // aimed now on their mean catches neither; one aimed at the launch, where each is seen, both.
  const auto futures = predictor.predict(
      {moving({2.0, 1.0, 2.0}, Eigen::Vector3d::Zero(), 0.5), moving({2.0, -1.0, 2.0}, Eigen::Vector3d::Zero(), 0.5)});
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, level_launch()).probability, 0.0);
  EXPECT_DOUBLE_EQ(capture_chance(futures, kNet, level_launch(), {}, true).probability, 1.0);
}
