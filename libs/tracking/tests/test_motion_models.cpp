// The constant-velocity and coordinated-turn models against their kinematics, and the IMM of
// constant velocity, constant acceleration and coordinated turn against targets whose motion is
// one of them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kestrel/tracking/imm_filter.hpp"
#include "kestrel/tracking/kalman_filter.hpp"
#include "kestrel/tracking/motion_models.hpp"

using namespace kestrel::tracking;

namespace {

// A state on a circle of radius R about the origin at height h, flown anticlockwise at speed v:
// at angle phi, p = R (cos, sin), v tangential, a centripetal.
State on_circle(double R, double v, double phi, double h = 5.0) {
  State x = State::Zero();
  const double w = v / R;
  x(index(0, 0)) = R * std::cos(phi), x(index(1, 0)) = R * std::sin(phi), x(index(2, 0)) = h;
  x(index(0, 1)) = -v * std::sin(phi), x(index(1, 1)) = v * std::cos(phi);
  x(index(0, 2)) = -v * w * std::cos(phi), x(index(1, 2)) = -v * w * std::sin(phi);
  return x;
}

}  // namespace

TEST(MotionModels, TheTurnRateIsReadFromVelocityAndAcceleration) {
  EXPECT_NEAR(turn_rate(on_circle(5.0, 5.0, 0.3)), 1.0, 1e-12);  // v / R, to the left
  State right = on_circle(4.0, 2.0, 1.0);
  right.segment<3>(3) *= -1.0;  // the same circle flown clockwise
  EXPECT_NEAR(turn_rate(right), -0.5, 1e-12);
  State slow = on_circle(1.0, 0.3, 0.0);  // below 0.5 m/s: no heading to turn
  EXPECT_EQ(turn_rate(slow), 0.0);
  EXPECT_EQ(turn_rate(on_circle(0.5, 6.0, 0.0)), 3.14159);  // 12 rad/s is no multirotor's: at most pi
}

TEST(MotionModels, ACoordinatedTurnStaysOnItsCircle) {
  // Noise-free, one step or many: the state a second later is the circle's, at constant speed.
  const State start = on_circle(5.0, 5.0, 0.2);
  const State one_step = model_transition(MotionModel::coordinated_turn, start, 1.0) * start;
  State many = start;
  for (int k = 0; k < 30; ++k) many = model_transition(MotionModel::coordinated_turn, many, 1.0 / 30) * many;
  const State truth = on_circle(5.0, 5.0, 1.2);
  EXPECT_LT((one_step - truth).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((many - truth).cwiseAbs().maxCoeff(), 1e-9);
  // The constant-acceleration model leaves the circle: its acceleration does not turn.
  const State ca = transition(1.0) * start;
  EXPECT_GT((ca.head<3>() - truth.head<3>()).norm(), 0.3);
}

TEST(MotionModels, WithoutATurnTheTurnIsConstantAccelerationAndConstantVelocityDropsIt) {
  State x = State::Zero();
  // Straight along x, speeding up at 1 m/s^2; climbing at 1 m/s, braking the climb at 2 m/s^2.
  x(index(0, 1)) = 3.0, x(index(0, 2)) = 1.0, x(index(2, 1)) = 1.0, x(index(2, 2)) = -2.0;
  EXPECT_EQ(turn_rate(x), 0.0);
  const State ct = model_transition(MotionModel::coordinated_turn, x, 0.5) * x;
  const State ca = transition(0.5) * x;
  EXPECT_LT((ct - ca).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(ct(index(0, 0)), 1.5 + 0.125, 1e-12);
  EXPECT_NEAR(ct(index(2, 0)), 0.5 - 0.25, 1e-12);  // z: v t + a t^2 / 2
  // Constant velocity: the acceleration is dropped, the velocity carried.
  const State cv = model_transition(MotionModel::constant_velocity, x, 0.5) * x;
  EXPECT_NEAR(cv(index(0, 0)), 1.5, 1e-12);
  EXPECT_NEAR(cv(index(2, 0)), 0.5, 1e-12);
  EXPECT_NEAR(cv(index(2, 1)), 1.0, 1e-12);
  EXPECT_EQ(cv(index(2, 2)), 0.0);
}

TEST(MotionModels, ConstantVelocityNoiseIsTheWhiteNoiseAccelerationModel) {
  // Q = integral over [0, dt] of F(s) G q G^T F(s)^T ds with G on the velocity: the closed form.
  const double dt = 0.2, q = 3.0;
  const Covariance Q = model_process_noise(MotionModel::constant_velocity, dt, q);
  EXPECT_DOUBLE_EQ(Q(index(0, 0), index(0, 0)), q * dt * dt * dt / 3.0);
  EXPECT_DOUBLE_EQ(Q(index(1, 0), index(1, 1)), q * dt * dt / 2.0);
  EXPECT_DOUBLE_EQ(Q(index(2, 1), index(2, 1)), q * dt);
  EXPECT_EQ(Q(index(0, 2), index(0, 2)), 0.0);
  EXPECT_EQ(Q(index(0, 0), index(1, 0)), 0.0);  // axes do not mix
  EXPECT_EQ(model_process_noise(MotionModel::coordinated_turn, dt, q), process_noise(dt, q));
}

namespace {

const std::vector<ImmModel> kThreeModels{{MotionModel::constant_velocity, 1.0},
                                         {MotionModel::constant_acceleration, 10.0},
                                         {MotionModel::coordinated_turn, 10.0}};

// Flies an IMM of cv, ca and ct along `truth(t)` for 6 s at 30 Hz with 0.05 m noise; returns the
// filter, and the RMS error over the last 3 s of its 0.5 s prediction, and of a ca filter's.
struct Flown {
  ImmTrack imm;
  double imm_prediction_rms, ca_prediction_rms;
};
template <class Truth>
Flown fly(Truth truth) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.05);
  const double dt = 1.0 / 30, r = 0.05 * 0.05, lead = 0.5;
  ImmTrack imm(truth(0.0), kThreeModels, 0.01, r, 1.0);
  KalmanTrack ca(truth(0.0), {10.0, r, 1.0});
  double imm_sq = 0, ca_sq = 0;
  int n = 0;
  for (int k = 1; k <= 180; ++k) {
    const double t = k * dt;
    const double nx = noise(rng), ny = noise(rng), nz = noise(rng);
    const Eigen::Vector3d z = truth(t) + Eigen::Vector3d(nx, ny, nz);
    imm.predict(dt), ca.predict(dt);
    imm.update(z), ca.update(z);
    if (t < 3.0) continue;
    const State x = ca.state();
    imm_sq += (imm.predicted_state(lead).head<3>() - truth(t + lead)).squaredNorm();
    ca_sq += ((transition(lead) * x).head<3>() - truth(t + lead)).squaredNorm();
    ++n;
  }
  return {imm, std::sqrt(imm_sq / n), std::sqrt(ca_sq / n)};
}

}  // namespace

TEST(ImmOfThreeModels, AStraightLineIsConstantVelocityAndATurnIsACoordinatedTurn) {
  const Flown line = fly([](double t) { return Eigen::Vector3d(2.0 + 4.0 * t, 1.0 - 3.0 * t, 5.0); });
  const auto& mu = line.imm.model_probabilities();
  ASSERT_EQ(mu.size(), 3u);
  EXPECT_NEAR(mu[0] + mu[1] + mu[2], 1.0, 1e-12);
  EXPECT_GT(mu[0], mu[1]);
  EXPECT_GT(mu[0], mu[2]);
  // A turn of 2 m radius at 5 m/s (12.5 m/s^2): the coordinated turn is the likeliest, and the
  // prediction half a second ahead, the time a net flies, is better than a constant acceleration's.
  const Flown turn = fly([](double t) {
    const double w = 2.5;
    return Eigen::Vector3d(2.0 * std::cos(w * t), 2.0 * std::sin(w * t), 5.0);
  });
  const auto& nu = turn.imm.model_probabilities();
  EXPECT_GT(nu[2], nu[0]);
  EXPECT_GT(nu[2], nu[1]);
  EXPECT_LT(turn.imm_prediction_rms, 0.5 * turn.ca_prediction_rms);
}

TEST(ImmOfThreeModels, PredictingAheadLeavesTheFilterAsItWas) {
  const Eigen::Vector3d start(1, 2, 3);
  ImmTrack imm(start, kThreeModels, 0.01, 0.01, 1.0);
  imm.predict(0.1);
  imm.update({1.2, 2.0, 3.0});
  const Eigen::VectorXd before = imm.state();
  const auto mu = imm.model_probabilities();
  (void)imm.predicted_state(0.7);
  EXPECT_EQ(imm.state(), before);
  EXPECT_EQ(imm.model_probabilities(), mu);
  // With no time ahead, the prediction is the estimate.
  EXPECT_LT((imm.predicted_state(0.0) - before).cwiseAbs().maxCoeff(), 1e-12);
}
