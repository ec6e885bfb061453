// The fire decision: the predicted shot on the net's ballistics, its probability, the trigger;
// and the world-frame target estimate it predicts from.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <random>

#include "fire_decision.hpp"
#include "target_estimate.hpp"

using namespace kestrel;
using namespace kestrel::aim;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TEST(FireTrigger, FiresAfterTheDwellAndNotAgainWithinTheCooldown) {
  FireTrigger fire(0.5, 0.5, 3.0);
  const double good = 0.22, bad = 0.6;
  EXPECT_FALSE(fire.update(0.0, good));
  EXPECT_FALSE(fire.update(0.3, good));
  EXPECT_FALSE(fire.update(0.4, bad));  // left the radius: the dwell starts again
  EXPECT_FALSE(fire.update(0.5, good));
  EXPECT_FALSE(fire.update(0.9, good));
  EXPECT_TRUE(fire.update(1.0, good));  // 0.5 s within
  EXPECT_FALSE(fire.update(1.6, good));
  EXPECT_FALSE(fire.update(3.9, good));  // within the cooldown
  EXPECT_TRUE(fire.update(4.0, good));
  EXPECT_FALSE(fire.update(10.0, std::nullopt));  // no target, no shot
}

TEST(FireTrigger, ATighterRadiusWaitsForABetterShot) {
  FireTrigger fire(0.5, 0.0, 0.0);
  EXPECT_FALSE(fire.update(0.0, 0.4, 0.3));  // good enough for a spare net, not for the last
  EXPECT_TRUE(fire.update(0.1, 0.25, 0.3));
  EXPECT_TRUE(fire.update(0.2, 0.4));  // the default radius
}

TEST(FireTrigger, WithoutADwellItFiresTheMomentTheMissIsWithinTheRadius) {
  FireTrigger fire(0.5, 0.0, 3.0);
  EXPECT_FALSE(fire.update(0.0, 0.51));
  EXPECT_TRUE(fire.update(0.033, 0.49));
  EXPECT_FALSE(fire.update(0.066, 0.1));                                     // cooldown
  EXPECT_FALSE(fire.update(5.0, std::numeric_limits<double>::quiet_NaN()));  // a NaN miss never fires
}

// The net of the paper's launcher: opens 0.4 s after the shot at x_E^d = [0, 1, 2] m (camera
// frame), stays open 0.3 s flying on. A level launcher at the origin looking along world +x.
TEST(PredictedMiss, IsTheLeastDistanceToTheNetWhileItIsOpen) {
  const net::NetModel net({Eigen::Vector3d(0.0, 1.0, 2.0), 0.4, 0.6, 0.3, 9.81});
  const auto launcher = geometry::level_camera(Eigen::Vector3d::Zero(), 0.0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();  // spelled out: Eigen leaves {} uninitialised
  // The opening point in the world: 2 m ahead, 1 m below.
  const Eigen::Vector3d open(2.0, 0.0, -1.0);
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {open, zero, zero}), 0.0, 1e-9);
  // A target hovering 0.3 m to the side of it: the net passes it at 0.3 m.
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {open + Eigen::Vector3d(0, 0.3, 0), zero, zero}),
              0.3, 1e-9);
  // A target crossing at 2 m/s that reaches the opening point at the opening: a hit, though it
  // is 0.8 m to the side when the shot leaves.
  const TargetMotion crossing{open - Eigen::Vector3d(0.0, 0.8, 0.0), Eigen::Vector3d(0.0, 2.0, 0.0), zero};
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), crossing), 0.0, 1e-9);
  // The net flies on after opening: a target where the net will be 0.15 s later is met there;
  // one where it would be after it closed is not.
  const net::NetShot shot = net.fire(0.0, launcher, Eigen::Vector3d::Zero());
  EXPECT_NEAR(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {net.position(shot, 0.55), zero, zero}), 0.0,
              1e-9);
  EXPECT_GT(predicted_miss(net, launcher, Eigen::Vector3d::Zero(), {net.position(shot, 0.9), zero, zero}), 0.6);
  // The launcher's own velocity carries the net: flying at 1 m/s sideways, the net meets a target
  // that drifts with it, and passes a hovering one 0.4 m to its side.
  const Eigen::Vector3d side(0.0, 1.0, 0.0);
  EXPECT_NEAR(predicted_miss(net, launcher, side, {open, side, zero}), 0.0, 1e-9);
  EXPECT_NEAR(predicted_miss(net, launcher, side, {open, zero, zero}), 0.4, 1e-9);
}

TEST(PredictedShot, GivesTheTimeAndTheVectorOfTheClosestApproach) {
  const net::NetModel net({Eigen::Vector3d(0.0, 1.0, 2.0), 0.4, 0.6, 0.3, 9.81});
  const auto launcher = geometry::level_camera(Eigen::Vector3d::Zero(), 0.0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const net::NetShot shot = net.fire(0.0, launcher, zero);
  // The net flies in the vertical plane of the launcher's heading (world x, z); a target hovering
  // 0.2 m beside the point it reaches 0.55 s after the launch is passed then, 0.2 m off.
  const Eigen::Vector3d beside(0.0, 0.2, 0.0);
  const PredictedShot s = predict_shot(net, launcher, zero, {net.position(shot, 0.55) + beside, zero, zero});
  EXPECT_NEAR(s.time_s, 0.55, 1e-9);
  EXPECT_TRUE(s.miss.isApprox(beside, 1e-9)) << s.miss.transpose();
}

namespace {
// A shot whose predicted miss is `miss` at one instant, half a second after the launch.
PredictedShot one_instant(const Eigen::Vector3d& miss) { return {0.5, miss, {{0.5, miss}}}; }
// An uncertainty in position alone, isotropic.
ShotUncertainty position_spread(double sigma) {
  ShotUncertainty u;
  u.position_velocity.topLeftCorner<3, 3>() = sigma * sigma * Eigen::Matrix3d::Identity();
  return u;
}
}  // namespace

// Known answers: a certain target is held exactly when its miss is within the radius; a target
// centred on the net with an isotropic spread sigma is held with the Maxwell distribution's
// probability of |z| <= R / sigma (R = sigma: erf(1/sqrt 2) - sqrt(2/pi) e^(-1/2) = 0.1987;
// R = 2 sigma: 0.7385).
TEST(HitProbability, IsTheShareOfThePredictedDistributionInsideTheNet) {
  const ShotUncertainty certain;
  EXPECT_EQ(hit_probability(one_instant({0.5, 0.0, 0.0}), certain, 0.6), 1.0);
  EXPECT_EQ(hit_probability(one_instant({0.0, 0.7, 0.0}), certain, 0.6), 0.0);
  const double sigma = 0.3;
  const ShotUncertainty spread = position_spread(sigma);
  EXPECT_NEAR(hit_probability(one_instant(Eigen::Vector3d::Zero()), spread, sigma), 0.1987, 0.02);
  EXPECT_NEAR(hit_probability(one_instant(Eigen::Vector3d::Zero()), spread, 2.0 * sigma), 0.7385, 0.02);
  // Further off, less likely; the same answer every time; a broken estimate never fires.
  EXPECT_LT(hit_probability(one_instant({0.4, 0.0, 0.0}), spread, 2.0 * sigma),
            hit_probability(one_instant({0.1, 0.0, 0.0}), spread, 2.0 * sigma));
  EXPECT_EQ(hit_probability(one_instant({0.2, 0.1, 0.0}), spread, 0.6),
            hit_probability(one_instant({0.2, 0.1, 0.0}), spread, 0.6));
  EXPECT_EQ(hit_probability(one_instant({kNaN, 0.0, 0.0}), spread, 0.6), 0.0);
  ShotUncertainty broken = spread;
  broken.position_velocity(4, 4) = kNaN;
  EXPECT_EQ(hit_probability(one_instant({0.1, 0.0, 0.0}), broken, 0.6), 0.0);
  EXPECT_EQ(hit_probability(PredictedShot{}, spread, 0.6), 0.0);  // no open window
  // Uncertain only across the miss: a spread along z does not move a target that is 0.5 m off in x
  // further than its spread allows.
  ShotUncertainty flat;
  flat.position_velocity(2, 2) = 0.01;
  EXPECT_GT(hit_probability(one_instant({0.5, 0.0, 0.0}), flat, 0.6), 0.99);
}

// An unknown velocity moves the target by dv s (s from the estimate to the instant): a target off by
// 0.2 m in x whose velocity is uncertain by 0.5 m/s in y is at s = 0.5 s within 0.6 m of the net
// when |0.2 + ...| stays inside: |dv_y| <= sqrt(0.6^2 - 0.2^2) / 0.5 = 1.13 m/s, 2.26 sigma:
// P = 0.976. The lead (estimate to launch) adds to s: at s = 1 s, 0.566 m/s, 1.13 sigma: 0.742.
TEST(HitProbability, AnUncertainVelocityGrowsWithTheTimeFromTheEstimate) {
  ShotUncertainty u;
  u.position_velocity(4, 4) = 0.25;
  const PredictedShot shot = one_instant({0.2, 0.0, 0.0});
  EXPECT_NEAR(hit_probability(shot, u, 0.6), 0.976, 0.015);
  u.lead_s = 0.5;
  EXPECT_NEAR(hit_probability(shot, u, 0.6), 0.742, 0.03);
}

// An unforeseen acceleration a moves the target by a s^2 / 2: with sigma_a = 4 m/s^2 and s = 0.5 s,
// 0.5 m per axis; centred on the net it is held while |z| <= 0.6 / 0.5 = 1.2. Without the
// manoeuvre it is held for certain.
TEST(HitProbability, AManoeuvreWhileTheNetFliesSpreadsTheTarget) {
  ShotUncertainty u;
  const PredictedShot shot = one_instant(Eigen::Vector3d::Zero());
  EXPECT_EQ(hit_probability(shot, u, 0.6), 1.0);
  u.manoeuvre_m_s2 = 4.0;
  // P(|z| <= 1.2) for a 3-D standard normal: erf(1.2 / sqrt 2) - sqrt(2 / pi) 1.2 e^(-0.72) = 0.304.
  EXPECT_NEAR(hit_probability(shot, u, 0.6), 0.304, 0.025);
  // An acceleration expected to go on moves the whole path: 2 m/s^2 by 0.25 m (still held), 8 m/s^2
  // by 1 m (never).
  ShotUncertainty expected;
  expected.acceleration_m_s2 = {2.0, 0.0, 0.0};
  EXPECT_EQ(hit_probability(shot, expected, 0.6), 1.0);
  expected.acceleration_m_s2 = {8.0, 0.0, 0.0};
  EXPECT_EQ(hit_probability(shot, expected, 0.6), 0.0);
  expected.acceleration_m_s2.x() = kNaN;
  EXPECT_EQ(hit_probability(shot, expected, 0.6), 0.0);
}

// The net sweeps its path while open: a target whose uncertain timing only moves it along the
// path (it crosses the net's path within the window) is caught whatever the timing, while the
// same miss at the window's edge, the target leaving the net's path, is caught only when early.
TEST(HitProbability, TheOpenNetSweepsThroughAnEarlyOrLateTarget) {
  ShotUncertainty u;
  u.position_velocity(0, 0) = 0.3 * 0.3;  // timing: where along x the target is
  PredictedShot crossing{0.55, {0.0, 0.3, 0.0}, {}}, leaving{0.4, {0.0, 0.3, 0.0}, {}};
  for (int i = 0; i <= 30; ++i) {
    const double tau = 0.4 + 0.01 * i;
    // Relative to the net the target moves along x at 10 m/s, crossing its path at 0.55 s ...
    crossing.path.push_back({tau, {10.0 * (tau - 0.55), 0.3, 0.0}});
    // ... or moves away from it across, along x, from the miss at the opening.
    leaving.path.push_back({tau, {10.0 * (tau - 0.4), 0.3, 0.0}});
  }
  // Held while |x| <= sqrt(0.6^2 - 0.3^2) = 0.52 at some instant. Crossing, x sweeps
  // [dx - 1.5, dx + 1.5]: held unless |dx| > 2.02 (6.7 sigma). Leaving, x sweeps [dx, dx + 3]:
  // held when dx <= 0.52 (1.73 sigma, P = 0.958).
  EXPECT_EQ(hit_probability(crossing, u, 0.6), 1.0);
  EXPECT_NEAR(hit_probability(leaving, u, 0.6), 0.958, 0.015);
  u.position_velocity(0, 0) = 1.0;  // 1 m: leaving, dx <= 0.52: P = 0.699; crossing |dx| <= 2.02: 0.957
  EXPECT_NEAR(hit_probability(leaving, u, 0.6), 0.699, 0.03);
  EXPECT_NEAR(hit_probability(crossing, u, 0.6), 0.957, 0.015);
}

// Each estimate follows a target flying straight at 3 m/s and predicts it half a second ahead; the
// IMM knows it flies at constant velocity; predicting ahead grows the uncertainty and leaves the
// estimate as it was.
TEST(TargetEstimate, EveryModelPredictsAStraightFlightAndTheImmKnowsItIsOne) {
  using M = TargetFilterConfig::Model;
  for (const M model : {M::constant_velocity, M::constant_acceleration, M::imm}) {
    SCOPED_TRACE(static_cast<int>(model));
    TargetEstimate e(Eigen::Vector3d(5, 0, 2), TargetFilterConfig{model, 10.0, 1.0, 10.0, 0.01, 0.02});
    for (int k = 1; k <= 60; ++k) {  // seen at 30 Hz
      e.predict(1.0 / 30.0);
      e.update(Eigen::Vector3d(5.0, 3.0 * k / 30.0, 2.0));
    }
    EXPECT_NEAR(e.state()(4), 3.0, 0.1);
    EXPECT_LT((e.position_after(0.5) - Eigen::Vector3d(5.0, 7.5, 2.0)).norm(), 0.05);
    const Eigen::VectorXd before = e.state();
    const Eigen::Matrix3d ahead = e.position_covariance_after(0.5);
    const Eigen::Matrix3d now = e.covariance().topLeftCorner(3, 3);
    EXPECT_GT(ahead.trace(), now.trace());
    EXPECT_EQ(e.state(), before);
    const auto mu = e.model_probabilities();
    if (model != M::imm) {
      EXPECT_TRUE(mu.empty());
      continue;
    }
    ASSERT_EQ(mu.size(), 3u);  // cv, ca, ct
    EXPECT_GT(mu[0], mu[1]);
    EXPECT_GT(mu[0], mu[2]);
  }
}
