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
