// The simulated vehicle's offboard rules against PX4's: no offboard without a setpoint stream,
// hold when the stream stops, no disarming in the air, an answer for every command.
#include <gmock/gmock.h>

#include "kestrel/mavlink/autopilot_modes.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "offboard_rules.hpp"

using namespace kestrel;
using namespace kestrel::mavlink;
using namespace kestrel::sim_autopilot;

namespace {

// A frame as the companion sends it (system 1, component 191), through the codec.
template <class M>
Frame from_companion(const M& message) {
  FrameParser parser;
  const auto frames = parser.feed(encode_v2(M::definition(), &message, {1, mav::comp_onboard_computer}, 0));
  EXPECT_EQ(frames.size(), 1u);
  return frames.front();
}

Frame setpoint() {
  SetPositionTargetLocalNed t;
  t.target_system = 1;
  t.target_component = 1;
  t.z = -2.0f;
  return from_companion(t);
}

Frame command(std::uint16_t id, float p1 = 0, float p2 = 0, float p3 = 0, std::uint8_t system = 1) {
  CommandLong c;
  c.target_system = system;
  c.target_component = 1;
  c.command = id;
  c.param1 = p1;
  c.param2 = p2;
  c.param3 = p3;
  return from_companion(c);
}

Frame ask_offboard() { return command(mav::cmd_do_set_mode, 1, 6); }

// Setpoints at `hz` from t0 for `seconds`.
void stream(OffboardRules& rules, double t0, double seconds, double hz) {
  for (double t = t0; t < t0 + seconds; t += 1.0 / hz) {
    rules.on_frame(setpoint(), t, true);
    rules.step(t);
  }
}

std::string mode_of(const OffboardRules& rules) { return mode_name(AutopilotKind::px4, rules.heartbeat().custom_mode); }

}  // namespace

TEST(OffboardRules, RefusesOffboardWithoutAStreamAndGrantsItWithOne) {
  OffboardRules rules;
  auto r = rules.on_frame(ask_offboard(), 0.0, true);
  ASSERT_TRUE(r.ack);
  EXPECT_EQ(r.ack->command, mav::cmd_do_set_mode);
  EXPECT_EQ(r.ack->result, mav::result_temporarily_rejected);
  EXPECT_EQ(r.ack->target_system, 1);
  EXPECT_EQ(r.ack->target_component, mav::comp_onboard_computer);
  EXPECT_EQ(mode_of(rules), "position");
  EXPECT_FALSE(rules.setpoint());

  stream(rules, 1.0, 1.0, 1.0);  // one setpoint a second: below PX4's 2 Hz
  EXPECT_EQ(rules.on_frame(ask_offboard(), 1.1, true).ack->result, mav::result_temporarily_rejected);
  stream(rules, 2.0, 0.5, 20.0);  // fast enough, but for half a second only
  EXPECT_EQ(rules.on_frame(ask_offboard(), 2.5, true).ack->result, mav::result_temporarily_rejected);
  stream(rules, 2.5, 0.5, 20.0);  // the same stream, a second long now
  EXPECT_EQ(rules.on_frame(ask_offboard(), 3.0, true).ack->result, mav::result_accepted);
  EXPECT_EQ(mode_of(rules), "offboard");
  ASSERT_TRUE(rules.setpoint());
  EXPECT_FLOAT_EQ(std::get<SetPositionTargetLocalNed>(rules.setpoint()->target).z, -2.0f);
  EXPECT_EQ(rules.counts().offboard_refusals, 3u);
  EXPECT_EQ(rules.counts().offboard_grants, 1u);
  EXPECT_THAT(rules.take_texts(), ::testing::Contains("Offboard mode"));
}

TEST(OffboardRules, SetpointsThatStopForTheLossTimeoutDropTheVehicleToHold) {
  OffboardRules rules(OffboardRulesOptions{.loss_timeout_s = 0.5});
  stream(rules, 0.0, 1.0, 50.0);
  rules.on_frame(ask_offboard(), 1.0, false);
  rules.step(1.4);
  EXPECT_EQ(mode_of(rules), "offboard") << "0.42 s since the last setpoint: still within the timeout";
  rules.step(1.6);
  EXPECT_EQ(mode_of(rules), "hold");
  EXPECT_FALSE(rules.setpoint());
  EXPECT_EQ(rules.counts().offboard_losses, 1u);
  // Setpoints again do not bring offboard back by themselves: it must be asked for.
  stream(rules, 2.0, 1.0, 50.0);
  EXPECT_EQ(mode_of(rules), "hold");
  EXPECT_EQ(rules.on_frame(ask_offboard(), 3.0, false).ack->result, mav::result_accepted);
  EXPECT_EQ(mode_of(rules), "offboard");
}

TEST(OffboardRules, ArmsAndRefusesToDisarmInTheAirUnlessForced) {
  OffboardRules rules;
  EXPECT_FALSE(is_armed(rules.heartbeat()));
  EXPECT_EQ(rules.on_frame(command(mav::cmd_component_arm_disarm, 1), 0.0, true).ack->result, mav::result_accepted);
  EXPECT_TRUE(rules.armed());
  EXPECT_TRUE(is_armed(rules.heartbeat()));
  EXPECT_EQ(rules.on_frame(command(mav::cmd_component_arm_disarm, 0), 1.0, false).ack->result, mav::result_denied);
  EXPECT_TRUE(rules.armed());
  EXPECT_EQ(rules.on_frame(command(mav::cmd_component_arm_disarm, 0, 21196), 1.0, false).ack->result,
            mav::result_accepted);
  EXPECT_FALSE(rules.armed());
  rules.on_frame(command(mav::cmd_component_arm_disarm, 1), 2.0, true);
  EXPECT_EQ(rules.on_frame(command(mav::cmd_component_arm_disarm, 0), 3.0, true).ack->result, mav::result_accepted);
  EXPECT_EQ(rules.counts().arms, 2u);
  EXPECT_EQ(rules.counts().disarms, 2u);
  EXPECT_EQ(rules.counts().refused_commands, 1u);
}

TEST(OffboardRules, ServoAndRelayCommandsAreCarriedOutAndOthersAnswered) {
  OffboardRules rules;
  const auto servo = rules.on_frame(command(mav::cmd_do_set_servo, 9, 1900), 0.0, false);
  ASSERT_TRUE(servo.output);
  EXPECT_FALSE(servo.output->relay);
  EXPECT_EQ(servo.output->channel, 9);
  EXPECT_DOUBLE_EQ(servo.output->value, 1900.0);
  EXPECT_EQ(servo.ack->result, mav::result_accepted);
  const auto relay = rules.on_frame(command(mav::cmd_do_set_relay, 2, 1), 0.0, false);
  ASSERT_TRUE(relay.output);
  EXPECT_TRUE(relay.output->relay);
  EXPECT_EQ(relay.output->channel, 2);
  const auto unknown = rules.on_frame(command(512), 0.0, false);  // REQUEST_MESSAGE: not simulated
  EXPECT_EQ(unknown.ack->result, mav::result_unsupported);
  EXPECT_FALSE(unknown.output);
  EXPECT_EQ(rules.counts().unsupported_commands, 1u);
  // For another vehicle: no answer, nothing done.
  const auto other = rules.on_frame(command(mav::cmd_do_set_servo, 9, 1900, 0, 2), 0.0, false);
  EXPECT_FALSE(other.ack);
  EXPECT_FALSE(other.output);
  EXPECT_EQ(rules.counts().outputs, 2u);
}

TEST(OffboardRules, TheHeartbeatNamesEachModeAsPx4Does) {
  OffboardRules rules;
  EXPECT_EQ(rules.heartbeat().autopilot, mav::autopilot_px4);
  EXPECT_EQ(rules.heartbeat().type, mav::type_quadrotor);
  rules.on_frame(command(mav::cmd_do_set_mode, 1, 4, 3), 0.0, false);  // AUTO.LOITER
  EXPECT_EQ(mode_of(rules), "hold");
  rules.on_frame(command(mav::cmd_do_set_mode, 1, 3), 0.0, false);
  EXPECT_EQ(mode_of(rules), "position");
  EXPECT_EQ(rules.on_frame(command(mav::cmd_do_set_mode, 1, 2), 0.0, false).ack->result, mav::result_unsupported);
}
