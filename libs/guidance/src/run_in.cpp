#include "kestrel/guidance/run_in.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::guidance {

ComponentSpec RunIn::spec() {
  using C = RunInConfig;
  ConfigSpec<C> c;
  c.param("stalk_range_m", &C::stalk_range_m)
      .with_unit("m")
      .range(1.0, 100.0)
      .describe("how far from the target (horizontally) the hunter waits before a run, beyond where it flees");
  c.param("height_m", &C::height_m)
      .with_unit("m")
      .range(-10.0, 10.0)
      .describe("the hunter above the target while it stalks and runs in: where the net, falling, crosses it");
  c.param("speed_m_s", &C::speed_m_s)
      .with_unit("m/s")
      .range(0.1, 50.0)
      .describe("the run's closing speed along the line of sight (relative to the target)");
  c.param("acceleration_m_s2", &C::acceleration_m_s2)
      .with_unit("m/s^2")
      .range(0.1, 50.0)
      .describe("the run-up's acceleration: the launcher tilts with it, and is level again at the run's speed");
  c.param("gain_1_s", &C::gain_1_s)
      .with_unit("1/s")
      .range(0.01, 20.0)
      .describe("pull towards the stalk point and height");
  c.param("settle_m", &C::settle_m)
      .with_unit("m")
      .range(0.01, 100.0)
      .describe("the run starts with the hunter within this of the stalk point");
  c.param("settle_speed_m_s", &C::settle_speed_m_s)
      .with_unit("m/s")
      .range(0.01, 100.0)
      .describe("and moving with the target within this");
  c.param("settle_s", &C::settle_s)
      .with_unit("s")
      .range(0.0, 100.0)
      .describe("for this long: the hunter, which lags its reference, is steady before the run-up");
  c.param("max_target_speed_m_s", &C::max_target_speed_m_s)
      .with_unit("m/s")
      .range(0.0, 100.0)
      .describe("and the target no faster than this (a fleeing target is waited out)");
  c.param("break_off_m", &C::break_off_m)
      .with_unit("m")
      .range(0.0, 100.0)
      .describe("the run ends this near the target (horizontally), and the stalk begins again");
  c.rule("break_off_m < stalk_range_m", {"break_off_m", "stalk_range_m"},
         [](const C& k) { return k.break_off_m < k.stalk_range_m; });
  return ComponentSpec("run_in", "A pass at speed from a stalk outside the target's flee radius")
      .details(
          "Stalks the target from stalk_range_m (horizontally) and height_m above it, with its velocity fed "
          "forward; once settled there for settle_s and the target slower than max_target_speed_m_s, runs in along the "
          "line of "
          "sight, speeding up at acceleration_m_s2 to speed_m_s relative to the target, and holds that speed. The "
          "net inherits the hunter's velocity, so the aim's probability fires it from several metres, before a "
          "target that reacts to a near hunter has moved. Within break_off_m the run ends and the stalk begins "
          "again. Never hands over to the terminal phase.")
      .config(std::move(c));
}

RunIn::RunIn(const ComponentInit& init) : cfg_(init.config<RunInConfig>()) {}

GuidanceCommand RunIn::command(const Engagement& e) {
  const Eigen::Vector2d to_target = (e.target.position - e.position).head<2>();
  const double range = to_target.norm();
  const Eigen::Vector2d line =
      range > 1e-6 ? Eigen::Vector2d(to_target / range) : Eigen::Vector2d(std::cos(e.yaw), std::sin(e.yaw));
  const double yaw = std::atan2(line.y(), line.x());
  const double height = std::max(e.target.position.z() + cfg_.height_m, e.min_altitude);
  const Eigen::Vector2d stalk = e.target.position.head<2>() - cfg_.stalk_range_m * line;
  const Eigen::Vector2d relative = (e.velocity - e.target.velocity).head<2>();

  if (running_ && range <= cfg_.break_off_m) running_ = false;
  if (!running_) {
    const bool settled =
        (stalk - e.position.head<2>()).norm() <= cfg_.settle_m && std::abs(height - e.position.z()) <= cfg_.settle_m &&
        relative.norm() <= cfg_.settle_speed_m_s && e.target.velocity.norm() <= cfg_.max_target_speed_m_s;
    settled_s_ = settled ? settled_s_ + e.dt : 0.0;
    running_ = settled_s_ >= cfg_.settle_s && range > cfg_.break_off_m;
    if (running_) settled_s_ = 0.0;
  }

  Eigen::Vector3d v = e.target.velocity;
  v.z() += cfg_.gain_1_s * (height - e.position.z());
  if (running_) {
    // Along the line of sight at the target's velocity plus the run's: the relative motion stays
    // on the line, so the line does not turn while the target holds its course.
    const double closing = std::min(cfg_.speed_m_s, std::max(0.0, relative.dot(line)) + cfg_.acceleration_m_s2 * e.dt);
    v.head<2>() += closing * line;
  } else {
    v.head<2>() += cfg_.gain_1_s * (stalk - e.position.head<2>());
  }
  return {v, yaw, false, std::nullopt};
}

}  // namespace kestrel::guidance
