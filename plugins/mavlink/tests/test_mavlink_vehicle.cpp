// The autopilot's state read into kestrel's: frames converted, modes named, the link judged.
#include <gmock/gmock.h>

#include <numbers>

#include "kestrel/mavlink/autopilot_modes.hpp"
#include "link_status.hpp"
#include "vehicle_state_conversion.hpp"

using namespace kestrel::mavlink;
using Eigen::Vector3d;
using std::numbers::pi;

namespace {
void expect_near(const Vector3d& a, const Vector3d& b) {
  EXPECT_LT((a - b).norm(), 1e-6) << a.transpose() << " vs " << b.transpose();
}
}  // namespace

TEST(MavlinkVehicleState, LocalPositionAndAttitudeBecomeEnuAndFlu) {
  LocalPositionNed p;
  p.x = 1;   // north
  p.y = 2;   // east
  p.z = -3;  // 3 m up
  p.vx = 0.5f;
  p.vz = 1.0f;           // sinking
  AttitudeQuaternion a;  // identity: level, nose north
  a.rollspeed = 0.1f;
  a.pitchspeed = 0.2f;
  a.yawspeed = 0.3f;
  const auto s = vehicle_state(p, a);
  expect_near(s.position, {2, 1, 3});
  expect_near(s.velocity, {0, 0.5, -1});
  expect_near(s.orientation * Vector3d::UnitX(), {0, 1, 0});  // nose north
  expect_near(s.orientation * Vector3d::UnitZ(), {0, 0, 1});
  expect_near(s.angular_velocity, {0.1, -0.2, -0.3});
}

TEST(MavlinkVehicleState, OdometryInTheBodyFrameIsTurnedIntoTheWorld) {
  Odometry o;
  o.frame_id = mav::frame_local_ned;
  o.child_frame_id = mav::frame_body_frd;
  o.q = {static_cast<float>(std::cos(pi / 4)), 0, 0, static_cast<float>(std::sin(pi / 4))};  // nose east
  o.vx = 2;                                                                                  // forward
  o.z = -10;
  const auto s = vehicle_state(o);
  ASSERT_TRUE(s);
  expect_near(s->velocity, {2, 0, 0});  // east
  expect_near(s->position, {0, 0, 10});
  expect_near(s->orientation * Vector3d::UnitX(), {1, 0, 0});

  Odometry drifting = o;
  drifting.frame_id = 20;  // LOCAL_FRD: not placed on a compass
  EXPECT_FALSE(vehicle_state(drifting));
  Odometry broken = o;
  broken.q = {0, 0, 0, 0};
  EXPECT_FALSE(vehicle_state(broken));
}

TEST(MavlinkModes, EachAutopilotsModesByName) {
  EXPECT_EQ(mode_name(AutopilotKind::px4, 6u << 16), "offboard");
  EXPECT_EQ(mode_name(AutopilotKind::px4, 3u << 16), "position");
  EXPECT_EQ(mode_name(AutopilotKind::px4, (4u << 16) | (3u << 24)), "hold");
  EXPECT_EQ(mode_name(AutopilotKind::ardupilot, 4), "guided");
  EXPECT_EQ(mode_name(AutopilotKind::ardupilot, 99), "custom 99");
  Heartbeat hb;
  hb.base_mode = mav::mode_flag_custom_mode_enabled | mav::mode_flag_safety_armed;
  hb.custom_mode = 6u << 16;
  EXPECT_TRUE(in_external_control(AutopilotKind::px4, hb));
  EXPECT_TRUE(is_armed(hb));
  EXPECT_FALSE(in_external_control(AutopilotKind::ardupilot, hb));
  hb.custom_mode = 4;
  EXPECT_TRUE(in_external_control(AutopilotKind::ardupilot, hb));
  const CommandLong px4 = request_external_control(AutopilotKind::px4, 1, 1);
  EXPECT_EQ(px4.command, mav::cmd_do_set_mode);
  EXPECT_EQ(px4.param1, 1.0f);
  EXPECT_EQ(px4.param2, 6.0f);
  EXPECT_EQ(request_external_control(AutopilotKind::ardupilot, 1, 1).param2, 4.0f);
}

TEST(MavlinkStatus, TheLinkIsUpWhileHeartbeatsAreFresh) {
  VehicleView view;
  const auto now = LinkClock::now();
  EXPECT_FALSE(link_up(view, now, 1.5)) << "never heard";
  view.heartbeat.autopilot = mav::autopilot_px4;
  view.heartbeat.base_mode = mav::mode_flag_custom_mode_enabled;
  view.heartbeat.custom_mode = 3u << 16;
  view.heartbeat_at = now - std::chrono::milliseconds(1000);
  const auto fresh = autopilot_status(view, now, 1.5);
  EXPECT_TRUE(fresh.link_up);
  EXPECT_EQ(fresh.autopilot, "px4");
  EXPECT_EQ(fresh.mode, "position");
  EXPECT_FALSE(fresh.armed);
  EXPECT_NEAR(fresh.heartbeat_age_s, 1.0, 1e-6);
  view.heartbeat_at = now - std::chrono::milliseconds(1600);
  EXPECT_FALSE(autopilot_status(view, now, 1.5).link_up);
}
