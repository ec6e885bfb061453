// The offboard session's phases against an autopilot whose answers the test writes.
#include <gmock/gmock.h>

#include "command_ack.hpp"
#include "offboard_session.hpp"

using namespace kestrel::mavlink;
using Phase = OffboardSession::Phase;
using kestrel::mavlink::testing::ack;

namespace {

AutopilotState px4(bool link_up, bool armed = false, bool offboard = false) {
  AutopilotState a;
  a.link_up = link_up;
  a.armed = armed;
  a.external_control = offboard;
  a.kind = AutopilotKind::px4;
  return a;
}

}  // namespace

TEST(OffboardSession, PrestreamsThenAsksForOffboardAndFlies) {
  OffboardSession s({});
  s.step(0.0, px4(false));
  EXPECT_EQ(s.phase(), Phase::waiting_for_autopilot);
  EXPECT_FALSE(s.streaming());
  s.step(0.1, px4(true));
  EXPECT_EQ(s.phase(), Phase::prestreaming);
  EXPECT_TRUE(s.streaming());
  s.step(0.6, px4(true));
  EXPECT_FALSE(s.command_due(0.6)) << "nothing is asked before a second of setpoints";
  s.step(1.1, px4(true));
  EXPECT_EQ(s.phase(), Phase::requesting_control);
  const auto request = s.command_due(1.1);
  ASSERT_TRUE(request);
  EXPECT_EQ(request->command, mav::cmd_do_set_mode);
  EXPECT_EQ(request->param2, 6.0f);
  s.on_ack(ack(mav::cmd_do_set_mode, mav::result_accepted));
  s.step(1.2, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::requesting_control) << "until the heartbeat shows the mode";
  s.step(1.5, px4(true, true, true));
  EXPECT_EQ(s.phase(), Phase::engaged);
  EXPECT_TRUE(s.flying(px4(true, true, true)));
  EXPECT_FALSE(s.flying(px4(true, false, true))) << "not armed: not flying";
  EXPECT_EQ(s.counts().arm_requests, 0u) << "arm: false never arms";
}

TEST(OffboardSession, ArmsOnlyWhenAskedToThenRequestsTheMode) {
  SessionOptions o;
  o.arm = true;
  OffboardSession s(o);
  s.step(0.0, px4(true));
  s.step(1.0, px4(true));
  EXPECT_EQ(s.phase(), Phase::arming);
  const auto arm = s.command_due(1.0);
  ASSERT_TRUE(arm);
  EXPECT_EQ(arm->command, mav::cmd_component_arm_disarm);
  EXPECT_EQ(arm->param1, 1.0f);
  s.on_ack(ack(mav::cmd_component_arm_disarm, mav::result_accepted));
  s.step(1.1, px4(true, true));
  EXPECT_EQ(s.phase(), Phase::requesting_control);
}

TEST(OffboardSession, ALostHeartbeatStopsTheStreamAndItsReturnStartsOver) {
  OffboardSession s({});
  s.step(0.0, px4(true));
  s.step(1.0, px4(true));
  s.on_ack(ack(mav::cmd_do_set_mode, mav::result_accepted));
  s.step(1.5, px4(true, true, true));
  ASSERT_EQ(s.phase(), Phase::engaged);
  s.step(3.0, px4(false, true, true));
  EXPECT_EQ(s.phase(), Phase::link_lost);
  EXPECT_FALSE(s.streaming());
  EXPECT_EQ(s.counts().link_losses, 1u);
  s.step(5.0, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::prestreaming) << "back through the pre-stream";
  s.step(5.5, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::prestreaming);
  s.step(6.0, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::requesting_control);
}

TEST(OffboardSession, WhenThePilotTakesOverItDoesNotAskAgain) {
  OffboardSession s({});
  s.step(0.0, px4(true));
  s.step(1.0, px4(true, true, true));
  ASSERT_EQ(s.phase(), Phase::engaged);
  s.step(2.0, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::released);
  s.step(9.0, px4(true, true, false));
  EXPECT_EQ(s.phase(), Phase::released);
  EXPECT_FALSE(s.command_due(9.0));
  EXPECT_EQ(s.counts().releases, 1u);
}

TEST(OffboardSession, ARefusalOrSilenceIsReportedAndNotRepeated) {
  OffboardSession s({});
  s.step(0.0, px4(true));
  s.step(1.0, px4(true));
  ASSERT_TRUE(s.command_due(1.0));
  s.on_ack(ack(mav::cmd_do_set_mode, mav::result_denied));
  s.step(1.1, px4(true));
  EXPECT_EQ(s.phase(), Phase::refused);
  EXPECT_THAT(s.refusal(), ::testing::HasSubstr("refused (MAV_RESULT 2)"));
  EXPECT_TRUE(s.streaming());

  SessionOptions quick;
  quick.retries = 1;
  OffboardSession silent(quick);
  silent.step(0.0, px4(true));
  silent.step(1.0, px4(true));
  int sends = 0;
  for (double t = 1.0; t < 6.0; t += 0.1) {
    if (silent.command_due(t)) ++sends;
    silent.step(t, px4(true));
  }
  EXPECT_EQ(sends, 2) << "the request and one retry";
  EXPECT_EQ(silent.phase(), Phase::refused);
  EXPECT_THAT(silent.refusal(), ::testing::HasSubstr("had no answer"));
}

TEST(OffboardSession, ATemporaryRejectionStreamsOnAndAsksAgainUpToTheRetries) {
  SessionOptions o;
  o.retries = 2;
  OffboardSession s(o);
  s.step(0.0, px4(true));
  s.step(1.0, px4(true));
  for (int rejection = 1; rejection <= 2; ++rejection) {
    const double t = 1.0 + 1.1 * (rejection - 1);
    ASSERT_TRUE(s.command_due(t)) << "request " << rejection;
    s.on_ack(ack(mav::cmd_do_set_mode, mav::result_temporarily_rejected));
    s.step(t + 0.05, px4(true));
    EXPECT_EQ(s.phase(), Phase::prestreaming) << "a stream a little short: another pre-stream";
    EXPECT_TRUE(s.streaming());
    EXPECT_FALSE(s.command_due(t + 0.5)) << "nothing asked within the pre-stream";
    s.step(t + 1.1, px4(true));
    EXPECT_EQ(s.phase(), Phase::requesting_control);
  }
  EXPECT_EQ(s.counts().temporary_rejections, 2u);
  EXPECT_EQ(s.counts().control_requests, 3u);
  ASSERT_TRUE(s.command_due(3.3));
  s.on_ack(ack(mav::cmd_do_set_mode, mav::result_temporarily_rejected));
  s.step(3.4, px4(true));
  EXPECT_EQ(s.phase(), Phase::refused) << "the retries spent";
  EXPECT_THAT(s.refusal(), ::testing::HasSubstr("refused (MAV_RESULT 1)"));
  EXPECT_EQ(s.counts().refusals, 1u);
}
