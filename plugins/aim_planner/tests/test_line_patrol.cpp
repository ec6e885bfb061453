// A target flying a line back and forth: the line, its ends and its turns found from sightings,
// and its motion predicted through a turn.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "line_patrol.hpp"

using namespace kestrel::aim;

namespace {
constexpr double kSightingPeriod_s = 1.0 / 30.0;

// A patrol between `from` and `to`: from rest up to `speed` at `accel`, cruising, braking at
// `accel` to rest at the far end, and back, as the simulated intruder's line flies.
struct Patrol {
  Eigen::Vector3d from, to;
  double speed, accel;

  double leg_s() const {
    const double length = (to - from).norm();
    return 2.0 * speed / accel + (length - speed * speed / accel) / speed;
  }
  // Distance from `from` at time t.
  double along(double t) const {
    const double length = (to - from).norm(), leg = leg_s(), ramp = speed / accel;
    const int n = static_cast<int>(std::floor(t / leg));
    const double u = t - n * leg;
    double s;
    if (u < ramp)
      s = 0.5 * accel * u * u;
    else if (u < leg - ramp)
      s = speed * speed / (2.0 * accel) + speed * (u - ramp);
    else
      s = length - 0.5 * accel * (leg - u) * (leg - u);
    return n % 2 == 0 ? s : length - s;
  }
  Eigen::Vector3d at(double t) const { return from + along(t) * (to - from).normalized(); }
  Eigen::Vector3d velocity(double t) const { return (at(t + 1e-4) - at(t - 1e-4)) / 2e-4; }
};

const Patrol kLine{{6.0, -4.0, 2.5}, {7.0, 6.0, 2.8}, 7.0, 5.0};

// Sightings of `patrol` from t0 to t1, `noise_m` off (Gaussian, per axis), none while `hidden`.
template <class Hidden>
void watch(LinePatrol& patrol, const Patrol& truth, double t0, double t1, double noise_m, Hidden hidden) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, noise_m);
  for (double t = t0; t < t1; t += kSightingPeriod_s) {
    if (hidden(t)) continue;
    patrol.add(t, truth.at(t) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
}
void watch(LinePatrol& patrol, const Patrol& truth, double t0, double t1, double noise_m = 0.05) {
  watch(patrol, truth, t0, t1, noise_m, [](double) { return false; });
}
}  // namespace

TEST(LinePatrol, FindsTheLineItsEndsAndHowItTurns) {
  LinePatrol patrol(LinePatrolConfig{});
  watch(patrol, kLine, 0.0, 8.0);
  const auto& line = patrol.line();
  ASSERT_TRUE(line);
  const Eigen::Vector3d direction = (kLine.to - kLine.from).normalized();
  EXPECT_NEAR(std::abs(line->direction.dot(direction)), 1.0, 1e-3);
  // Each end where the target turned, to a few centimetres, though the sightings are 5 cm off.
  const int far = line->direction.dot(direction) > 0.0 ? 1 : 0;
  EXPECT_TRUE(line->turned[0] && line->turned[1]);
  EXPECT_LT((line->end(far) - kLine.to).norm(), 0.08);
  EXPECT_LT((line->end(1 - far) - kLine.from).norm(), 0.08);
  EXPECT_NEAR(line->deceleration_m_s2, kLine.accel, 0.5);
  EXPECT_NEAR(line->cruise_speed_m_s, kLine.speed, 0.5);
  EXPECT_LT(line->rms_residual_m, 0.12);
}

TEST(LinePatrol, NoTurnWhereTheTargetOnlyLeftTheView) {
  // Seen only while it is more than 3 m from the far end: it leaves the view and comes back near
  // the same point, which is no turn; the near end, seen whole, is one.
  LinePatrol patrol(LinePatrolConfig{});
  const auto near_far_end = [](double t) { return (kLine.at(t) - kLine.to).norm() < 3.0; };
  watch(patrol, kLine, 0.0, 8.0, 0.05, near_far_end);
  const auto& line = patrol.line();
  ASSERT_TRUE(line);
  const int far = line->direction.dot(kLine.to - kLine.from) > 0.0 ? 1 : 0;
  EXPECT_FALSE(line->turned[static_cast<std::size_t>(far)]);
  EXPECT_TRUE(line->turned[static_cast<std::size_t>(1 - far)]);
  // A sighting beyond the end it turned at is off the patrol; beyond the other, on its line.
  const Eigen::Vector3d outward = (line->end(1 - far) - line->end(far)).normalized();
  EXPECT_TRUE(std::isinf(line->distance(line->end(1 - far) + 4.0 * outward, 3.0)));
  EXPECT_NEAR(line->distance(line->end(far) - 4.0 * outward, 3.0), 0.0, 1e-9);

  // Only ever seen crossing the middle: no turn at all, so no patrol.
  LinePatrol crossing(LinePatrolConfig{});
  watch(crossing, kLine, 0.0, 8.0, 0.05, [](double t) { return std::abs(kLine.along(t) - 5.0) > 3.5; });
  EXPECT_FALSE(crossing.line());
}

TEST(LinePatrol, AFigureEightShortOrWanderingFlightIsNoPatrol) {
  // A figure-8 in a vertical plane, 3 m wide and 0.6 m high: its sightings lie off any line.
  LinePatrol eight(LinePatrolConfig{});
  for (double t = 0.0; t < 8.0; t += kSightingPeriod_s)
    eight.add(t, Eigen::Vector3d(6.0, 3.0 * std::sin(1.5 * t), 2.5 + 0.6 * std::sin(3.0 * t)));
  EXPECT_FALSE(eight.line());

  // A line flown back and forth 2 m long, shorter than min_length_m (3).
  LinePatrol short_line(LinePatrolConfig{.min_length_m = 3.0});
  watch(short_line, Patrol{{6.0, 0.0, 2.5}, {6.0, 2.0, 2.5}, 2.0, 4.0}, 0.0, 8.0);
  EXPECT_FALSE(short_line.line());
  EXPECT_FALSE(LinePatrol(LinePatrolConfig{}).line());  // nothing seen
}

TEST(LinePatrol, KeepsItsLineAndItsEndsAsItIsFittedAgain) {
  LinePatrol patrol(LinePatrolConfig{});
  watch(patrol, kLine, 0.0, 8.0);
  ASSERT_TRUE(patrol.line());
  const Eigen::Vector3d end0 = patrol.line()->end(0);
  // Later sightings, and then far-end ones 1 m off the line (deep and noisy): the fit they make
  // is refused, the line stays, and end 0 stays the same end.
  watch(patrol, kLine, 8.0, 20.0);
  ASSERT_TRUE(patrol.line());
  EXPECT_LT((patrol.line()->end(0) - end0).norm(), 0.1);
  watch(patrol, kLine, 20.0, 26.0, 1.0);
  ASSERT_TRUE(patrol.line());
  EXPECT_LT((patrol.line()->end(0) - end0).norm(), 0.1);
  EXPECT_NEAR(*patrol.last_sighting_s(), 26.0, kSightingPeriod_s + 1e-9);
  patrol.reset();
  EXPECT_FALSE(patrol.line());
  EXPECT_FALSE(patrol.last_sighting_s());
}

TEST(LinePatrol, PredictsTheTargetThroughItsTurn) {
  LinePatrol patrol(LinePatrolConfig{});
  watch(patrol, kLine, 0.0, 8.0, 0.02);
  const auto& line = patrol.line();
  ASSERT_TRUE(line);
  // Cruising towards the far end, braking, at rest, turned back and speeding up: wherever it is,
  // the prediction 0.7 s on lies within 0.15 m of where it will be. A constant velocity would
  // put it metres beyond the end.
  const double leg = kLine.leg_s();
  for (double t = 8.0; t < 8.0 + 2.0 * leg; t += 0.1) {
    const double tau = 0.7;
    const Eigen::Vector3d predicted = line->predict(kLine.at(t), kLine.velocity(t), tau, 10.0);
    EXPECT_LT((predicted - kLine.at(t + tau)).norm(), 0.15) << "at t = " << t;
  }
  // Into the turn, a constant velocity is metres out.
  const double braking = leg - kLine.speed / kLine.accel;  // the first leg's braking starts
  EXPECT_GT((kLine.at(braking) + 0.7 * kLine.velocity(braking) - kLine.at(braking + 0.7)).norm(), 1.0);
}

TEST(LinePatrol, WaitsBeyondTheEndFacingAlongTheLine) {
  PatrolLine line;
  line.centre = Eigen::Vector3d(6.0, 0.0, 2.5);
  line.direction = Eigen::Vector3d(0.0, 1.0, 0.0);
  line.half_length_m = 4.0;
  const Eigen::Vector3d lookout = patrol_lookout(line, 1, 3.0);
  EXPECT_TRUE(lookout.isApprox(Eigen::Vector3d(6.0, 7.0, 2.5)));
  EXPECT_TRUE(patrol_lookout(line, 0, 3.0).isApprox(Eigen::Vector3d(6.0, -7.0, 2.5)));
}
