// ENU/FLU <-> NED/FRD against cases worked by hand.
#include <gmock/gmock.h>

#include <kestrel/geometry/ned_enu.hpp>
#include <numbers>

using namespace kestrel::geometry;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using std::numbers::pi;

namespace {
void expect_near(const Vector3d& a, const Vector3d& b) {
  EXPECT_LT((a - b).norm(), 1e-12) << a.transpose() << " vs " << b.transpose();
}
}  // namespace

TEST(NedEnu, PositionsAndVelocitiesSwapNorthAndEastAndFlipUp) {
  // 3 m east, 4 m north, 5 m up is 4 m north, 3 m east, 5 m down (-5).
  expect_near(enu_to_ned({3, 4, 5}), {4, 3, -5});
  expect_near(ned_to_enu({4, 3, -5}), {3, 4, 5});
  expect_near(ned_to_enu(enu_to_ned({-1.5, 0.25, 7})), {-1.5, 0.25, 7});
}

TEST(NedEnu, BodyRatesKeepRollAndFlipPitchAndYaw) {
  // Turning left (positive yaw rate about FLU's up) is a negative yaw rate about FRD's down.
  expect_near(flu_to_frd({0.1, 0.2, 0.3}), {0.1, -0.2, -0.3});
  expect_near(frd_to_flu({0.1, -0.2, -0.3}), {0.1, 0.2, 0.3});
}

TEST(NedEnu, AttitudesOfKnownHeadings) {
  // Level, nose east: identity in ENU/FLU; in NED/FRD a yaw of +90 degrees (east of north).
  const Quaterniond east = enu_flu_to_ned_frd(Quaterniond::Identity());
  expect_near(east * Vector3d::UnitX(), {0, 1, 0});  // forward points east in NED
  expect_near(east * Vector3d::UnitZ(), {0, 0, 1});  // FRD's down is NED's down
  EXPECT_NEAR(std::abs(east.w()), std::cos(pi / 4), 1e-12);
  EXPECT_NEAR(std::abs(east.z()), std::sin(pi / 4), 1e-12);

  // Level, nose north: yaw 90 degrees in ENU, identity in NED.
  const Quaterniond north(Eigen::AngleAxisd(pi / 2, Vector3d::UnitZ()));
  EXPECT_NEAR(std::abs(enu_flu_to_ned_frd(north).w()), 1.0, 1e-12);

  // Nose east, pitched 10 degrees up: in NED the nose's vector has a negative down component.
  const Quaterniond climbing(Eigen::AngleAxisd(-10 * pi / 180, Vector3d::UnitY()));
  const Vector3d nose = enu_flu_to_ned_frd(climbing) * Vector3d::UnitX();
  expect_near(nose, {0, std::cos(10 * pi / 180), -std::sin(10 * pi / 180)});

  // Any attitude goes there and back, and rotates vectors consistently with the frame maps.
  const Quaterniond q = Quaterniond(Eigen::AngleAxisd(0.7, Vector3d(1, -2, 3).normalized()));
  const Quaterniond back = ned_frd_to_enu_flu(enu_flu_to_ned_frd(q));
  EXPECT_NEAR(std::abs(back.dot(q)), 1.0, 1e-12);
  const Vector3d v_flu(0.3, -1.2, 2.0);
  expect_near(enu_flu_to_ned_frd(q) * flu_to_frd(v_flu), enu_to_ned(q * v_flu));
}

TEST(NedEnu, HeadingsTurnTheOtherWayFromTheOtherAxis) {
  EXPECT_NEAR(yaw_enu_to_ned(0.0), pi / 2, 1e-12);  // east
  EXPECT_NEAR(yaw_enu_to_ned(pi / 2), 0.0, 1e-12);  // north
  EXPECT_NEAR(yaw_enu_to_ned(pi), -pi / 2, 1e-12);  // west
  EXPECT_NEAR(yaw_enu_to_ned(-pi / 2), pi, 1e-12);  // south
  EXPECT_NEAR(yaw_ned_to_enu(yaw_enu_to_ned(2.5)), 2.5, 1e-12);
  EXPECT_NEAR(wrap_angle(3 * pi), pi, 1e-12);
}
