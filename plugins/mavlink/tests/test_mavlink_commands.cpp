// The command protocol's retries and results on a clock the test turns.
#include <gmock/gmock.h>

#include "command_ack.hpp"
#include "command_exchange.hpp"

using namespace kestrel::mavlink;
using kestrel::mavlink::testing::ack;

namespace {
CommandLong arm() {
  CommandLong c;
  c.command = mav::cmd_component_arm_disarm;
  c.param1 = 1;
  return c;
}
}  // namespace

TEST(CommandExchange, AnAcceptedCommandIsSentOnce) {
  CommandExchange x(1.0, 3);
  x.start(arm(), 0.0);
  const auto first = x.due(0.0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->confirmation, 0);
  EXPECT_FALSE(x.due(0.5));
  x.on_ack(ack(mav::cmd_do_set_mode, mav::result_accepted));  // another command's
  EXPECT_EQ(x.state(), CommandExchange::State::waiting);
  x.on_ack(ack(mav::cmd_component_arm_disarm, mav::result_in_progress));
  EXPECT_EQ(x.state(), CommandExchange::State::waiting);
  x.on_ack(ack(mav::cmd_component_arm_disarm, mav::result_accepted));
  EXPECT_EQ(x.state(), CommandExchange::State::accepted);
  EXPECT_FALSE(x.due(5.0));
  EXPECT_EQ(x.counts().sent, 1u);
  EXPECT_EQ(x.counts().resent, 0u);
}

TEST(CommandExchange, SilenceBringsRetriesWithTheirConfirmationThenATimeout) {
  CommandExchange x(1.0, 2);
  x.start(arm(), 0.0);
  ASSERT_TRUE(x.due(0.0));
  EXPECT_FALSE(x.due(0.9));
  const auto second = x.due(1.0);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->confirmation, 1);
  const auto third = x.due(2.0);
  ASSERT_TRUE(third);
  EXPECT_EQ(third->confirmation, 2);
  EXPECT_FALSE(x.due(3.0));
  EXPECT_EQ(x.state(), CommandExchange::State::timed_out);
  EXPECT_EQ(x.counts().resent, 2u);
  EXPECT_EQ(x.counts().timed_out, 1u);
}

TEST(CommandExchange, ADenialEndsItRefusedWithTheResult) {
  CommandExchange x(1.0, 3);
  x.start(arm(), 0.0);
  ASSERT_TRUE(x.due(0.0));
  x.on_ack(ack(mav::cmd_component_arm_disarm, mav::result_denied));
  EXPECT_EQ(x.state(), CommandExchange::State::refused);
  EXPECT_EQ(x.last_result(), mav::result_denied);
  EXPECT_FALSE(x.due(10.0));
  x.reset();
  EXPECT_EQ(x.state(), CommandExchange::State::idle);
}
