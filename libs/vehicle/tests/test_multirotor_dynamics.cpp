// The simulated multirotor against answers known in closed form: free fall, torque-free rotation,
// hover equilibrium, first-order motor lag, the ground, rotor drag, and the rotor geometry.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/vehicle/multirotor.hpp>
#include <kestrel/vehicle/multirotor_dynamics.hpp>
#include <kestrel/vehicle/wind.hpp>

using namespace kestrel;
using namespace kestrel::vehicle;

namespace {

const vehicle::Multirotor kFirefly = vehicle::Multirotor::firefly();

RigidBodyState at_rest(const Eigen::Vector3d& position, double rotor_speed = 0.0) {
  RigidBodyState s;
  s.position = position;
  s.rotor_speeds = Eigen::VectorXd::Constant(6, rotor_speed);
  return s;
}

Environment free_space() {
  Environment e;
  e.ground_z = -std::numeric_limits<double>::infinity();
  return e;
}

}  // namespace

TEST(MultirotorGeometry, FireflyRotorsAndWrenchMatrix) {
  ASSERT_EQ(kFirefly.rotors.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(kFirefly.rotors[k].angle_rad, M_PI / 6 + k * M_PI / 3, 1e-12);
    EXPECT_EQ(kFirefly.rotors[k].direction, k % 2 == 0 ? 1 : -1);
  }
  const Eigen::MatrixXd a = kFirefly.wrench_matrix();
  const double kf = 8.54858e-6, l = 0.215, km = 0.016;
  // Rotor 0 at 30 degrees (front left), counter-clockwise: its thrust rolls the body by
  // l sin 30 kf, pitches it by -l cos 30 kf, and its drag turns the body clockwise.
  EXPECT_NEAR(a(0, 0), l * 0.5 * kf, 1e-15);
  EXPECT_NEAR(a(1, 0), -l * std::sqrt(3.0) / 2 * kf, 1e-15);
  EXPECT_NEAR(a(2, 0), -km * kf, 1e-15);
  EXPECT_NEAR(a(3, 0), kf, 1e-15);
  // Rotor 1 at 90 degrees (left), clockwise.
  EXPECT_NEAR(a(0, 1), l * kf, 1e-15);
  EXPECT_NEAR(a(1, 1), 0.0, 1e-15);
  EXPECT_NEAR(a(2, 1), km * kf, 1e-15);
  // Equal speeds: thrust only.
  const Eigen::Vector4d w = a * Eigen::VectorXd::Constant(6, 500.0 * 500.0);
  EXPECT_NEAR(w.head<3>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(w(3), 6 * kf * 250000.0, 1e-9);
}

TEST(MultirotorGeometry, HoverSpeedBalancesGravity) {
  const double w = kFirefly.hover_rotor_speed_rad_s(9.81);
  EXPECT_NEAR(6 * 8.54858e-6 * w * w, 1.56779 * 9.81, 1e-9);
  EXPECT_NEAR(w, 547.6, 0.1);
}

TEST(MultirotorDynamics, FreeFallIsTheParabola) {
  const MultirotorDynamics d(kFirefly);
  RigidBodyState s = at_rest({1.0, 2.0, 100.0});
  s.velocity = {0.5, -0.25, 3.0};
  const Eigen::VectorXd off = Eigen::VectorXd::Zero(6);
  const double dt = 0.002;
  for (int i = 0; i < 1000; ++i) d.step(s, off, free_space(), dt);
  const double t = 2.0;
  // Rotors still: no thrust and no rotor drag, so the flight is exact for RK4 (a quadratic).
  EXPECT_NEAR(s.position.x(), 1.0 + 0.5 * t, 1e-9);
  EXPECT_NEAR(s.position.y(), 2.0 - 0.25 * t, 1e-9);
  EXPECT_NEAR(s.position.z(), 100.0 + 3.0 * t - 0.5 * 9.81 * t * t, 1e-9);
  EXPECT_NEAR(s.velocity.z(), 3.0 - 9.81 * t, 1e-9);
}

TEST(MultirotorDynamics, TorqueFreeSpinKeepsMomentumAndEnergy) {
  const MultirotorDynamics d(kFirefly);
  const Eigen::Vector3d j = kFirefly.inertia_kg_m2;
  // About an axis that is not principal: the body tumbles, but in the world frame its angular
  // momentum is constant, and so is its kinetic energy.
  RigidBodyState s = at_rest({0, 0, 0});
  s.angular_velocity = {1.0, 2.0, 0.5};
  auto momentum = [&](const RigidBodyState& x) { return x.orientation * j.cwiseProduct(x.angular_velocity).eval(); };
  auto energy = [&](const RigidBodyState& x) {
    return 0.5 * x.angular_velocity.dot(j.cwiseProduct(x.angular_velocity));
  };
  const Eigen::Vector3d l0 = momentum(s);
  const double e0 = energy(s);
  const Eigen::VectorXd off = Eigen::VectorXd::Zero(6);
  Environment weightless = free_space();
  weightless.gravity = 0.0;
  for (int i = 0; i < 10000; ++i) d.step(s, off, weightless, 0.001);
  EXPECT_LT((momentum(s) - l0).norm(), 1e-7 * l0.norm());
  EXPECT_NEAR(energy(s), e0, 1e-7 * e0);
  EXPECT_GT((s.angular_velocity - Eigen::Vector3d(1.0, 2.0, 0.5)).norm(), 0.1);  // it did tumble

  // About a principal axis: a steady rotation, exp(w t).
  RigidBodyState spin = at_rest({0, 0, 0});
  spin.angular_velocity = {0.0, 0.0, 2.0};
  for (int i = 0; i < 1000; ++i) d.step(spin, off, weightless, 0.001);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(spin.orientation.angularDistance(expected), 0.0, 1e-9);
}

TEST(MultirotorDynamics, HoverSpeedsHoldTheVehicleStill) {
  const MultirotorDynamics d(kFirefly);
  const double w = kFirefly.hover_rotor_speed_rad_s(9.81);
  RigidBodyState s = at_rest({0, 0, 5.0}, w);
  const Eigen::VectorXd hover = Eigen::VectorXd::Constant(6, w);
  for (int i = 0; i < 2000; ++i) d.step(s, hover, free_space(), 0.001);
  EXPECT_LT((s.position - Eigen::Vector3d(0, 0, 5.0)).norm(), 1e-9);
  EXPECT_LT(s.angular_velocity.norm(), 1e-12);
}

TEST(MultirotorDynamics, MotorsFollowWithFirstOrderLagUpAndDown) {
  const MultirotorDynamics d(kFirefly);
  RigidBodyState s = at_rest({0, 0, 100.0});
  const Eigen::VectorXd target = Eigen::VectorXd::Constant(6, 500.0);
  const double dt = 0.0001;
  // One time constant up: 1 - 1/e of the step.
  for (int i = 0; i < 125; ++i) d.step(s, target, free_space(), dt);
  EXPECT_NEAR(s.rotor_speeds(0), 500.0 * (1.0 - std::exp(-1.0)), 1e-6);
  // Then settled, then down by one (slower) time constant.
  for (int i = 0; i < 5000; ++i) d.step(s, target, free_space(), dt);
  EXPECT_NEAR(s.rotor_speeds(0), 500.0, 1e-6);
  const Eigen::VectorXd off = Eigen::VectorXd::Zero(6);
  for (int i = 0; i < 250; ++i) d.step(s, off, free_space(), dt);
  EXPECT_NEAR(s.rotor_speeds(0), 500.0 * std::exp(-1.0), 1e-6);
  // Commands beyond the motors' range are clipped.
  for (int i = 0; i < 5000; ++i) d.step(s, Eigen::VectorXd::Constant(6, 5000.0), free_space(), dt);
  EXPECT_NEAR(s.rotor_speeds.maxCoeff(), 838.0, 1e-6);
}

TEST(MultirotorDynamics, RestsOnTheGroundUntilTheRotorsLiftIt) {
  const MultirotorDynamics d(kFirefly);
  const Environment ground;  // z = 0
  RigidBodyState s = at_rest({0, 0, 0});
  const double hover = kFirefly.hover_rotor_speed_rad_s(9.81);
  for (int i = 0; i < 1000; ++i) d.step(s, Eigen::VectorXd::Constant(6, 0.9 * hover), ground, 0.001);
  EXPECT_EQ(s.position.z(), 0.0);
  EXPECT_TRUE(d.on_ground());
  for (int i = 0; i < 1000; ++i) d.step(s, Eigen::VectorXd::Constant(6, 1.1 * hover), ground, 0.001);
  EXPECT_GT(s.position.z(), 0.1);
  EXPECT_FALSE(d.on_ground());
  // Dropped from 2 m with the rotors stopped: it lands and stays at z = 0, never below.
  RigidBodyState drop = at_rest({0, 0, 2.0});
  double lowest = 2.0;
  for (int i = 0; i < 3000; ++i) {
    d.step(drop, Eigen::VectorXd::Zero(6), ground, 0.001);
    lowest = std::min(lowest, drop.position.z());
  }
  EXPECT_EQ(lowest, 0.0);
  EXPECT_EQ(drop.velocity.norm(), 0.0);
}

TEST(MultirotorDynamics, RotorDragOpposesTheAirspeedAcrossTheDiscs) {
  const MultirotorDynamics d(kFirefly);
  RigidBodyState s = at_rest({0, 0, 5.0}, 500.0);
  s.velocity = {2.0, 0.0, 1.0};
  const auto calm = d.rotor_wrench(s, Eigen::Vector3d::Zero());
  EXPECT_NEAR(calm.force.x(), -8.06428e-5 * 6 * 500.0 * 2.0, 1e-12);
  EXPECT_NEAR(calm.force.y(), 0.0, 1e-12);
  // Moving with the wind: no airspeed, no drag.
  const auto along = d.rotor_wrench(s, Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_NEAR(along.force.x(), 0.0, 1e-12);
}

TEST(Wind, GustsHaveTheirStandardDeviationAndAreReproducible) {
  Wind a({1.0, 0.0, 0.0}, 0.5, 1.0, 7), b({1.0, 0.0, 0.0}, 0.5, 1.0, 7);
  double sum = 0.0, squares = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d w = a.advance(0.01);
    EXPECT_EQ(w, b.advance(0.01));
    sum += w.y();
    squares += w.y() * w.y();
  }
  EXPECT_NEAR(sum / n, 0.0, 0.05);
  EXPECT_NEAR(std::sqrt(squares / n), 0.5, 0.05);
  Wind steady({1.0, 2.0, 0.0}, 0.0, 1.0, 7);
  EXPECT_EQ(steady.advance(0.1), Eigen::Vector3d(1.0, 2.0, 0.0));
}
