// The constant-acceleration Kalman filter, the IMM filter and the track-management components
// (initiator, deleter, selector), against hand-computed values and the continuous-time model.
#include <gmock/gmock.h>

#include <functional>
#include <random>

#include "kestrel/error.hpp"
#include "kestrel/testing/fixed_filter.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/deleter.hpp"
#include "kestrel/tracking/imm_filter.hpp"
#include "kestrel/tracking/initiator.hpp"
#include "kestrel/tracking/kalman_filter.hpp"
#include "kestrel/tracking/selector.hpp"

using namespace kestrel;
using namespace kestrel::tracking;
using kestrel::testing::FixedFilter;

TEST(ConstantAcceleration, TransitionIsTheKinematicModel) {
  const auto F = transition(0.1);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 0)), 1.0);
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 1)), 0.1);
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 2)), 0.005);
    EXPECT_DOUBLE_EQ(F(index(a, 1), index(a, 2)), 0.1);
    EXPECT_DOUBLE_EQ(F(index(a, 2), index(a, 1)), 0.0);
  }
  EXPECT_EQ((F.array() != 0).count(), 18);  // 9 ones + 3 x (dt, dt^2/2, dt): axes do not mix
}

TEST(ConstantAcceleration, ProcessNoiseIsTheDiscreteWhiteNoiseJerkModel) {
  // Q = integral over [0, dt] of F(s) G q G^T F(s)^T ds, with G = (0, 0, 1) per axis: integrate
  // numerically and compare with the closed form.
  const double dt = 0.2, q = 3.0;
  Covariance integral = Covariance::Zero();
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const double s = (i + 0.5) * dt / steps;
    const Covariance F = transition(s);
    Eigen::Matrix<double, 9, 3> G = Eigen::Matrix<double, 9, 3>::Zero();
    for (int a = 0; a < 3; ++a) G(index(a, 2), a) = 1.0;
    integral += F * G * (q * Eigen::Matrix3d::Identity()) * G.transpose() * F.transpose() * (dt / steps);
  }
  const Covariance Q = process_noise(dt, q);
  EXPECT_LT((Q - integral).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_DOUBLE_EQ(Q(index(0, 0), index(0, 0)), q * std::pow(dt, 5) / 20);
  EXPECT_DOUBLE_EQ(Q(index(1, 1), index(1, 2)), q * dt * dt / 2);
  EXPECT_DOUBLE_EQ(Q(index(2, 2), index(2, 2)), q * dt);
  EXPECT_DOUBLE_EQ(Q(index(0, 0), index(1, 0)), 0.0);
}

TEST(ConstantAcceleration, InitialCovarianceIsThePapers) {
  const auto P = initial_covariance(2.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(P(index(a, 0), index(a, 0)), 2.0 * 1.0);
    EXPECT_DOUBLE_EQ(P(index(a, 1), index(a, 1)), 2.0 * 900.0);
    EXPECT_DOUBLE_EQ(P(index(a, 2), index(a, 2)), 2.0 * 30.25);
  }
}

TEST(ConstantAcceleration, PredictAndUpdateMatchHandComputedValues) {
  auto kf = ConstantAccelerationKalman::start({1, 2, 3}, 1.0);
  kf.predict(0.1, 0.0);
  // Position variance after predict: 1 + dt^2 900 + (dt^2/2)^2 30.25.
  const double pp = 1.0 + 0.01 * 900.0 + 0.005 * 0.005 * 30.25;
  EXPECT_NEAR(kf.P(0, 0), pp, 1e-12);
  EXPECT_NEAR(kf.P(index(0, 0), index(0, 1)), 0.1 * 900.0 + 0.005 * 0.1 * 30.25, 1e-12);  // cov(x, v)
  EXPECT_TRUE(kf.position().isApprox(Eigen::Vector3d(1, 2, 3)));
  // Update x with z = 1.5, r = 1: gain on position pp / (pp + 1); on velocity cov(x,v) / (pp + 1).
  const double pxv = kf.P(index(0, 0), index(0, 1));
  kf.update({1.5, 2, 3}, 1.0);
  EXPECT_NEAR(kf.x(index(0, 0)), 1.0 + pp / (pp + 1.0) * 0.5, 1e-12);
  EXPECT_NEAR(kf.x(index(0, 1)), pxv / (pp + 1.0) * 0.5, 1e-12);
  EXPECT_NEAR(kf.P(0, 0), pp - pp * pp / (pp + 1.0), 1e-9);
  EXPECT_NEAR(kf.x(index(1, 0)), 2.0, 1e-12);  // other axes untouched
}

TEST(ConstantAcceleration, TracksAConstantAcceleration) {
  auto kf = ConstantAccelerationKalman::start({0, 0, 5}, 1.0);
  const double dt = 1.0 / 30;
  for (int k = 1; k <= 300; ++k) {
    kf.predict(dt, 0.01);
    const double t = k * dt;
    kf.update({0.5 * 0.8 * t * t, 2.0 * t, 5.0}, 0.01);
  }
  EXPECT_NEAR(kf.x(index(0, 2)), 0.8, 0.02);
  EXPECT_NEAR(kf.x(index(1, 1)), 2.0, 0.02);
}

// ---- The components, each on a case whose answer is known.

TEST(Initiator, ConsecutiveHitsStartsATrackPerUnclaimedDetectionAndConfirmsAtTheNthHit) {
  const ConsecutiveHitsInitiator three(ConsecutiveHitsConfig{3});
  const std::vector<Eigen::Vector3d> detections = {{0, 0, 5}, {1, 0, 5}, {2, 0, 5}};
  EXPECT_THAT(three.initiate(detections, {0, 2}), ::testing::ElementsAre(0u, 2u));
  EXPECT_TRUE(three.initiate(detections, {}).empty());
  TrackStatus t;
  t.hits = 2;
  EXPECT_FALSE(three.confirms(t));
  t.hits = 3;
  EXPECT_TRUE(three.confirms(t));
  EXPECT_FALSE(three.drops(t));
  t.misses = 1;
  EXPECT_TRUE(three.drops(t));  // a tentative track dies at its first miss
  t.hits = 1;
  t.misses = 0;
  EXPECT_TRUE(ConsecutiveHitsInitiator(ConsecutiveHitsConfig{1}).confirms(t));  // the paper: at birth
}

TEST(Deleter, ConsecutiveMissesDeletesAtTheMissAfterMaxMisses) {
  const ConsecutiveMissesDeleter deleter(ConsecutiveMissesConfig{10});
  TrackStatus t;
  t.confirmed = true;
  t.misses = 10;
  EXPECT_FALSE(deleter.deletes(t));
  t.misses = 11;
  EXPECT_TRUE(deleter.deletes(t));
  t.misses = 1;
  EXPECT_TRUE(ConsecutiveMissesDeleter(ConsecutiveMissesConfig{0}).deletes(t));
}

namespace {

// Three confirmed tracks: 1 is the oldest, 2 has the most hits, 3 is the nearest and the most
// certain.
struct Candidates {
  FixedFilter far{{0, 0, 9}, 4.0}, mid{{0, 0, 6}, 2.0}, near{{0, 0, 3}, 0.5};
  std::vector<TrackStatus> tracks{{1, 30, 12, 3, true, &far}, {2, 20, 20, 0, true, &mid}, {3, 10, 10, 0, true, &near}};
};

}  // namespace

TEST(Selector, EachRuleOnAKnownCase) {
  const Candidates c;
  EXPECT_EQ(*LongestLivingSelector().select(c.tracks), 1u);
  EXPECT_EQ(*MostHitsSelector().select(c.tracks), 2u);
  EXPECT_EQ(*NearestSelector().select(c.tracks), 3u);
  EXPECT_EQ(*MostConfidentSelector().select(c.tracks), 3u);
  // Most confident is not nearest: make the near track uncertain.
  FixedFilter uncertain_near({0, 0, 3}, 9.0);
  auto tracks = c.tracks;
  tracks[2].filter = &uncertain_near;
  EXPECT_EQ(*NearestSelector().select(tracks), 3u);
  EXPECT_EQ(*MostConfidentSelector().select(tracks), 2u);
  EXPECT_FALSE(LongestLivingSelector().select({}));
}

namespace {

// A target flying straight at 2 m/s, then turning hard (5 m/s^2 across its path for 0.6 s),
// then straight again, measured at 30 Hz with 0.05 m noise. Returns the RMS position error of
// the filter over the steady legs and over the turn and the second after it.
struct LegErrors {
  double steady = 0, manoeuvre = 0;
};
template <class Track>
LegErrors fly_a_turn(Track& track, std::vector<double>* manoeuvre_probability = nullptr) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  const double dt = 1.0 / 30;
  Eigen::Vector3d p(0, 0, 5), v(2, 0, 0);
  double steady_sq = 0, turn_sq = 0;
  int steady_n = 0, turn_n = 0;
  for (int k = 1; k <= 300; ++k) {
    const double t = k * dt;
    const bool turning = t >= 4.0 && t < 4.6;
    const Eigen::Vector3d a =
        turning ? Eigen::Vector3d(Eigen::Vector3d(-v.y(), v.x(), 0).normalized() * 5.0) : Eigen::Vector3d::Zero();
    p += v * dt + 0.5 * a * dt * dt;
    v += a * dt;
    track.predict(dt);
    const double nz = noise(rng), ny = noise(rng), nx = noise(rng);  // in sequence, z first, for every compiler
    track.update(p + Eigen::Vector3d(nx, ny, nz));
    const double e2 = (track.state().template head<3>() - p).squaredNorm();
    if (t >= 4.0 && t < 5.6) {
      turn_sq += e2, ++turn_n;
      if (manoeuvre_probability) manoeuvre_probability->push_back(0);
    } else if (t >= 2.0) {
      steady_sq += e2, ++steady_n;
    }
    if constexpr (requires { track.model_probabilities(); })
      if (manoeuvre_probability && t >= 4.0 && t < 5.6) manoeuvre_probability->back() = track.model_probabilities()[1];
  }
  return {std::sqrt(steady_sq / steady_n), std::sqrt(turn_sq / turn_n)};
}

}  // namespace

TEST(Imm, SmoothAsTheSteadyModelAndAgileAsTheManoeuvreModel) {
  using namespace kestrel::tracking;
  const Eigen::Vector3d start(0, 0, 5);
  const double r = 0.05 * 0.05;
  KalmanTrack steady(start, {1.0, r, 1.0}), agile(start, {1000.0, r, 1.0});
  ImmTrack imm(start, {1.0, 1000.0, 0.01, r, 1.0});
  std::vector<double> manoeuvre;
  const LegErrors s = fly_a_turn(steady), a = fly_a_turn(agile), i = fly_a_turn(imm, &manoeuvre);
  // The steady filter is the smoothest in straight flight and lags in the turn; the agile one
  // follows the turn and passes the noise on. The IMM beats each where the other is good.
  EXPECT_LT(s.steady, a.steady);
  EXPECT_GT(s.manoeuvre, a.manoeuvre);
  EXPECT_LT(i.steady, 0.75 * a.steady);
  EXPECT_LT(i.manoeuvre, 0.9 * s.manoeuvre);
  // It knows when the target manoeuvres.
  ASSERT_FALSE(manoeuvre.empty());
  EXPECT_GT(*std::max_element(manoeuvre.begin(), manoeuvre.end()), 0.5);
  const auto& mu = imm.model_probabilities();
  EXPECT_NEAR(mu[0] + mu[1], 1.0, 1e-12);
  EXPECT_GT(mu[0], 0.5);  // straight again at the end: steady
}
