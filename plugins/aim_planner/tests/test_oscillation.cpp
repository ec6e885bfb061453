// The target as an oscillator: the figure-8 the capture benchmark flies is two sinusoids, a
// straight flight none; a figure-8's turn is predicted where constant velocity misses it by a
// metre.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "oscillation.hpp"

using namespace kestrel::aim;

namespace {
constexpr double kSightingInterval_s = 1.0 / 30.0;

// The intruder's figure-8 (plugins/intruder_trajectory): across the view and up, about a centre.
struct EightPath {
  Eigen::Vector3d centre{6.0, 1.0, 2.5};
  double half_width = 2.0, half_height = 0.5, omega = 2.0;
  Eigen::Vector3d at(double t) const {
    return centre + Eigen::Vector3d(0.0, half_width * std::sin(omega * t), half_height * std::sin(2.0 * omega * t));
  }
};

// Sightings every frame for `seconds`, `noise_m` off per axis.
template <typename Path>
OscillationPredictor sight(const Path& path, double seconds, double noise_m) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, noise_m);
  OscillationPredictor predictor{OscillationConfig{}};
  for (double t = 0.0; t <= seconds + 1e-9; t += kSightingInterval_s)
    predictor.add(t, path(t) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  return predictor;
}
}  // namespace

TEST(Oscillation, AFigureEightIsTwoSinusoidsAboutItsCentre) {
  const EightPath eight;
  const auto predictor = sight([&](double t) { return eight.at(t); }, 4.0, 0.0);
  const auto& axes = predictor.axes();
  EXPECT_FALSE(axes[0]);  // the depth does not move
  ASSERT_TRUE(axes[1] && axes[2]);
  EXPECT_NEAR(axes[1]->omega_rad_s, eight.omega, 0.04 * eight.omega);  // the grid's step
  EXPECT_NEAR(axes[2]->omega_rad_s, 2.0 * eight.omega, 0.08 * eight.omega);
  EXPECT_NEAR(axes[1]->centre, eight.centre.y(), 0.1);
  EXPECT_NEAR(axes[2]->centre, eight.centre.z(), 0.1);
}

TEST(Oscillation, PredictsAFigureEightsTurnThatConstantVelocityMisses) {
  const EightPath eight;  // 4 m/s through its centre, turning at up to 8 m/s^2
  // Sightings 4 cm off, as the detection-level camera's at 6 m.
  const double now = 4.0, tau = 0.55;  // the net's flight to its closest approach
  const auto predictor = sight([&](double t) { return eight.at(t); }, now, 0.04);
  const auto& axes = predictor.axes();
  ASSERT_TRUE(axes[1] && axes[2]);
  const Eigen::Vector2d predicted(OscillationPredictor::position_after(*axes[1], tau),
                                  OscillationPredictor::position_after(*axes[2], tau));
  const double error = (predicted - eight.at(now + tau).tail<2>()).norm();
  EXPECT_LT(error, 0.15);
  // Constant velocity from the truth's own state misses by far more.
  const Eigen::Vector3d velocity = (eight.at(now + 1e-4) - eight.at(now - 1e-4)) / 2e-4;
  EXPECT_GT((eight.at(now) + velocity * tau - eight.at(now + tau)).norm(), 1.0);
}

TEST(Oscillation, AStraightOrSteadilyTurningFlightIsNoOscillation) {
  const Eigen::Vector3d start(6.0, -3.0, 2.0), velocity(0.5, 4.0, 0.2), acceleration(0.0, -1.0, 0.5);
  for (const double noise : {0.0, 0.04}) {
    const auto predictor =
        sight([&](double t) { return Eigen::Vector3d(start + velocity * t + 0.5 * acceleration * t * t); }, 3.0, noise);
    for (const auto& axis : predictor.axes()) EXPECT_FALSE(axis) << "noise " << noise;
  }
}

TEST(Oscillation, NoFitOnTooFewSightings) {
  const EightPath eight;
  const auto predictor = sight([&](double t) { return eight.at(t); }, 10 * kSightingInterval_s, 0.0);
  for (const auto& axis : predictor.axes()) EXPECT_FALSE(axis);
}

TEST(Oscillation, TheWindowForgetsOldSightings) {
  // A figure-8 that stops and hovers: after a window of hovering, no oscillation is left.
  const EightPath eight;
  const auto predictor = sight([&](double t) { return t < 4.0 ? eight.at(t) : eight.at(4.0); }, 4.0 + 2.6, 0.0);
  for (const auto& axis : predictor.axes()) EXPECT_FALSE(axis);
}

// A swing that leaves the view comes back where the fit says: 0.6 s after the last sighting (a
// figure-8's end, out of the camera's view), the oscillation puts it within 0.2 m of the truth;
// the axis that does not oscillate keeps the caller's prediction.
TEST(Oscillation, PredictsWhereALostSwingComesBack) {
  const EightPath eight;
  const double last = 4.0, later = 4.6;
  const auto predictor = sight([&](double t) { return eight.at(t); }, last, 0.04);
  const Eigen::Vector3d elsewhere(7.5, -20.0, 40.0);
  const Eigen::Vector3d expected = predictor.predict(later - last, elsewhere);
  EXPECT_EQ(expected.x(), elsewhere.x());
  EXPECT_LT((expected.tail<2>() - eight.at(later).tail<2>()).norm(), 0.2);
  // Constant velocity from the last sighting would be over a metre off.
  const Eigen::Vector3d velocity = (eight.at(last + 1e-4) - eight.at(last - 1e-4)) / 2e-4;
  EXPECT_GT((eight.at(last) + velocity * (later - last) - eight.at(later)).norm(), 1.0);
}

// The aim at the swing's centre: the figure-8's 2 m swing across the view is aimed at its centre,
// at rest; its 0.5 m swing up and down, under the least amplitude, and the depth are the target's.
TEST(Oscillation, TheSwingCentreAimWaitsWhereTheWideSwingComesThrough) {
  const EightPath eight;
  const double now = 4.3;  // the target off the centre, flying
  const auto predictor = sight([&](double t) { return eight.at(t); }, now, 0.0);
  const Eigen::Vector3d position = eight.at(now);
  const Eigen::Vector3d velocity = (eight.at(now + 1e-4) - eight.at(now - 1e-4)) / 2e-4;
  ASSERT_GT(std::abs(position.y() - eight.centre.y()), 1.0);
  const SwingAim aim = swing_centre_aim(predictor, position, velocity, SwingBounds{1.0, 4.0, 0.1});
  // The wide swing across and, with it, the narrow one up: the figure-8 crosses both centres at once.
  EXPECT_EQ(aim.waiting, (std::array<bool, 3>{false, true, true}));
  EXPECT_NEAR(aim.position.y(), eight.centre.y(), 0.05);
  EXPECT_NEAR(aim.position.z(), eight.centre.z(), 0.05);
  EXPECT_GT(std::abs(position.z() - eight.centre.z()), 0.1);  // the target itself is off it
  EXPECT_EQ(aim.velocity.y(), 0.0);
  EXPECT_EQ(aim.velocity.z(), 0.0);
  EXPECT_EQ(aim.position.x(), position.x());  // the depth, which does not swing, as it is
  EXPECT_EQ(aim.velocity.x(), velocity.x());
  // Its peak speed is sqrt((2 m * 2/s)^2 + (0.5 m * 4/s)^2) = 4.47 m/s: a bound above it still waits.
  EXPECT_EQ(swing_centre_aim(predictor, position, velocity, SwingBounds{1.0, 4.0, 0.1, 4.6}).waiting,
            (std::array<bool, 3>{false, true, true}));
  // Swings narrower or wider than the bounds, fitted less closely, or faster, leave the target as it is.
  for (const SwingBounds& bounds : {SwingBounds{2.5, 4.0, 0.1}, SwingBounds{0.1, 0.4, 0.1}, SwingBounds{0.1, 4.0, 0.0},
                                    SwingBounds{1.0, 4.0, 0.1, 4.3}}) {
    const SwingAim follow = swing_centre_aim(predictor, position, velocity, bounds);
    EXPECT_EQ(follow.waiting, (std::array<bool, 3>{})) << bounds.min_amplitude_m << " to " << bounds.max_amplitude_m;
    EXPECT_EQ(follow.position, position);
    EXPECT_EQ(follow.velocity, velocity);
  }
}
