// The run-in on engagements whose outcome is known: it waits at the stalk point until settled,
// runs in along a line of sight that does not turn while the target holds its course, reaches its
// speed at its run-up's acceleration and holds it, breaks off near the target and stalks again;
// a fast target is never run at.
#include <gmock/gmock.h>

#include <kestrel/guidance/aim_reference.hpp>
#include <kestrel/guidance/run_in.hpp>

using namespace kestrel::guidance;

namespace {

struct Flight {
  std::optional<double> run_at;        ///< when the first run began
  double range_at_run = 0.0;           ///< horizontal, then
  double height_at_run = 0.0;          ///< hunter above target, then
  double closing_at_run = 0.0;         ///< m/s along the line of sight, then
  double max_closing = 0.0;            ///< m/s along the line of sight while running
  double max_run_acceleration = 0.0;   ///< m/s^2 along the line while running
  double line_turned_rad = 0.0;        ///< the line of sight's largest turn while running
  std::optional<double> broke_off_at;  ///< when the first run ended
  double farthest_after = 0.0;         ///< horizontal range, the farthest after the first run
};

// A hunter that flies its reference exactly, against a target at constant velocity.
Flight fly(RunIn& law, const Eigen::Vector3d& target_start, const Eigen::Vector3d& target_velocity, double duration_s,
           const Eigen::Vector3d& hunter_start = {0.0, 0.0, 3.0}) {
  const double dt = 1.0 / 30.0;
  AimReference reference({1.0, 12.0, 8.0, 2.0}, hunter_start, 0.0);
  Flight out;
  Eigen::Vector2d run_line = Eigen::Vector2d::Zero();
  double last_closing = 0.0;
  for (double t = 0.0; t < duration_s; t += dt) {
    Engagement e;
    e.dt = dt;
    e.position = reference.position();
    e.velocity = reference.velocity();
    e.yaw = reference.yaw();
    e.target.position = target_start + target_velocity * t;
    e.target.velocity = target_velocity;
    e.limits = {12.0, 8.0};
    const bool was_running = law.running();
    const GuidanceCommand c = law.command(e);
    EXPECT_FALSE(c.terminal);
    reference.steer(c.velocity, c.yaw, dt);
    const Eigen::Vector2d to_target = (target_start + target_velocity * (t + dt) - reference.position()).head<2>();
    const double closing = (reference.velocity() - target_velocity).head<2>().dot(to_target.normalized());
    if (law.running() && !was_running && !out.run_at) {
      out.run_at = t;
      out.range_at_run = to_target.norm();
      out.height_at_run = reference.position().z() - e.target.position.z();
      out.closing_at_run = last_closing;
      run_line = to_target.normalized();
    } else if (law.running() && !out.broke_off_at) {
      out.max_closing = std::max(out.max_closing, closing);
      out.max_run_acceleration = std::max(out.max_run_acceleration, (closing - last_closing) / dt);
      out.line_turned_rad =
          std::max(out.line_turned_rad, std::acos(std::min(1.0, run_line.dot(to_target.normalized()))));
    } else if (was_running && !out.broke_off_at) {
      out.broke_off_at = t;
    }
    last_closing = closing;
    if (out.broke_off_at) out.farthest_after = std::max(out.farthest_after, to_target.norm());
  }
  return out;
}

}  // namespace

TEST(RunIn, StalksThenRunsInAtItsSpeedAlongALineOfSightThatDoesNotTurn) {
  RunInConfig k;
  RunIn law(k);
  // A target cruising across at 1.5 m/s, 25 m ahead: the hunter first closes to the stalk point.
  const Flight f = fly(law, {25.0, -3.0, 2.5}, {0.0, 1.5, 0.0}, 12.0);
  ASSERT_TRUE(f.run_at);
  EXPECT_NEAR(f.range_at_run, k.stalk_range_m, k.settle_m + 0.1);
  EXPECT_NEAR(f.height_at_run, k.height_m, k.settle_m + 0.1);
  EXPECT_NEAR(f.max_closing, k.speed_m_s, 1e-6);
  EXPECT_LE(f.max_run_acceleration, k.acceleration_m_s2 + 1e-6);
  EXPECT_LT(f.line_turned_rad, 0.02);
  ASSERT_TRUE(f.broke_off_at);
  // From the stalk range, up to speed at the run-up's acceleration, then at speed to break_off_m.
  EXPECT_LE(std::abs(f.closing_at_run), k.settle_speed_m_s);
  const double run_up_s = (k.speed_m_s - f.closing_at_run) / k.acceleration_m_s2;
  const double run_up_m = 0.5 * (k.speed_m_s + f.closing_at_run) * run_up_s;
  const double expected_s = run_up_s + (f.range_at_run - run_up_m - k.break_off_m) / k.speed_m_s;
  EXPECT_NEAR(*f.broke_off_at - *f.run_at, expected_s, 0.15);
}

TEST(RunIn, AfterTheRunItStalksAgain) {
  RunInConfig k;
  RunIn law(k);
  // A hovering target: one run, then back out to the stalk range.
  const Flight f = fly(law, {20.0, 0.0, 2.5}, Eigen::Vector3d::Zero(), 14.0);
  ASSERT_TRUE(f.run_at && f.broke_off_at);
  EXPECT_GT(f.farthest_after, k.stalk_range_m - k.settle_m);
}

TEST(RunIn, NeverRunsAtATargetFasterThanItsBound) {
  RunInConfig k;
  RunIn law(k);
  const Flight f = fly(law, {20.0, -10.0, 2.5}, {0.0, k.max_target_speed_m_s + 1.0, 0.0}, 8.0);
  EXPECT_FALSE(f.run_at);
}

TEST(RunIn, ANewTargetIsStalkedFirst) {
  RunIn first(RunInConfig{});
  const Flight whole = fly(first, {20.0, 0.0, 2.5}, Eigen::Vector3d::Zero(), 10.0);
  ASSERT_TRUE(whole.run_at && whole.broke_off_at);
  // The same flight stopped halfway through its run: a reset forgets the run.
  RunIn law(RunInConfig{});
  fly(law, {20.0, 0.0, 2.5}, Eigen::Vector3d::Zero(), 0.5 * (*whole.run_at + *whole.broke_off_at));
  ASSERT_TRUE(law.running());
  law.reset();
  EXPECT_FALSE(law.running());
}
