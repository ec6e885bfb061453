// The mixer gives the wrench asked for when the motors can; beyond that, attitude first gives up
// thrust before yaw, and yaw before roll and pitch, and clipping keeps the thrust. Whatever it
// gives, the motors give.
#include <gtest/gtest.h>

#include <kestrel/vehicle/multirotor.hpp>
#include <kestrel/vehicle/rotor_mixer.hpp>

using namespace kestrel::vehicle;

namespace {

const Multirotor kMixed = Multirotor::firefly();  // six rotors, 36 N at full speed

Eigen::Vector4d wrench_of(const Eigen::VectorXd& speeds) { return kMixed.wrench_matrix() * speeds.cwiseAbs2(); }

void expect_within_range(const Eigen::VectorXd& speeds) {
  EXPECT_GE(speeds.minCoeff(), 0.0);
  EXPECT_LE(speeds.maxCoeff(), kMixed.max_rotor_speed_rad_s + 1e-9);
}

}  // namespace

TEST(RotorMixer, AWrenchWithinReachIsGivenExactly) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::attitude);
  const auto mix = mixer.mix({0.3, -0.2, 0.05}, 16.0);
  EXPECT_FALSE(mix.saturated);
  EXPECT_TRUE(wrench_of(mix.speeds).isApprox(Eigen::Vector4d(0.3, -0.2, 0.05, 16.0), 1e-9));
}

TEST(RotorMixer, NearFullThrustTheThrustGivesWayAndTheTorqueIsKept) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::attitude);
  const double full = kMixed.max_thrust_n();
  const Eigen::Vector3d torque(1.0, 0.5, 0.0);
  const auto mix = mixer.mix(torque, full);
  EXPECT_TRUE(mix.saturated);
  expect_within_range(mix.speeds);
  const Eigen::Vector4d given = wrench_of(mix.speeds);
  EXPECT_TRUE(given.head<3>().isApprox(torque, 1e-9)) << given.transpose();
  EXPECT_LT(given(3), full);
  // As little as the torque needs: the fastest rotor still at its top speed.
  EXPECT_NEAR(mix.speeds.maxCoeff(), kMixed.max_rotor_speed_rad_s, 1e-6);
  EXPECT_NEAR(given(3), mix.thrust_n, 1e-6);
}

TEST(RotorMixer, ClippingInsteadKeepsTheThrustAndLosesTheTorque) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::clip);
  const double full = kMixed.max_thrust_n();
  const auto mix = mixer.mix({1.0, 0.5, 0.0}, full);
  EXPECT_TRUE(mix.saturated);
  expect_within_range(mix.speeds);
  const Eigen::Vector4d given = wrench_of(mix.speeds);
  EXPECT_GT(given(3), 0.9 * full);
  EXPECT_LT(given.head<2>().norm(), 0.8 * Eigen::Vector2d(1.0, 0.5).norm());
}

TEST(RotorMixer, AtLowThrustTheThrustRisesToKeepTheTorque) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::attitude);
  const Eigen::Vector3d torque(1.0, 0.0, 0.0);
  const auto mix = mixer.mix(torque, 0.5);
  EXPECT_TRUE(mix.saturated);
  expect_within_range(mix.speeds);
  const Eigen::Vector4d given = wrench_of(mix.speeds);
  EXPECT_TRUE(given.head<3>().isApprox(torque, 1e-9)) << given.transpose();
  EXPECT_GT(given(3), 0.5);
  EXPECT_NEAR(mix.speeds.minCoeff(), 0.0, 1e-6);  // no more than the torque needs
}

TEST(RotorMixer, YawGivesWayBeforeRollAndPitch) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::attitude);
  const double hover = kMixed.mass_kg * 9.81;
  const Eigen::Vector3d torque(0.8, -0.6, 5.0);  // far more yaw than the rotors' drag gives
  const auto mix = mixer.mix(torque, hover);
  EXPECT_TRUE(mix.saturated);
  expect_within_range(mix.speeds);
  const Eigen::Vector4d given = wrench_of(mix.speeds);
  EXPECT_NEAR(given(0), 0.8, 1e-6);
  EXPECT_NEAR(given(1), -0.6, 1e-6);
  EXPECT_GT(given(2), 0.0);  // what yaw is left, the same way
  EXPECT_LT(given(2), 5.0);
}

TEST(RotorMixer, ARollAndPitchBeyondReachKeepsItsDirectionWithNoYaw) {
  const RotorMixer mixer(kMixed, RotorMixer::Priority::attitude);
  const Eigen::Vector3d torque(30.0, 40.0, 1.0);
  const auto mix = mixer.mix(torque, 10.0);
  EXPECT_TRUE(mix.saturated);
  expect_within_range(mix.speeds);
  const Eigen::Vector4d given = wrench_of(mix.speeds);
  EXPECT_NEAR(given(2), 0.0, 1e-6);
  EXPECT_NEAR(given(1) / given(0), 40.0 / 30.0, 1e-6);
  EXPECT_GT(given.head<2>().norm(), 1.0);  // as much as the rotors give, not nothing
}
