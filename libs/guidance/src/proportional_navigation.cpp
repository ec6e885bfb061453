#include "kestrel/guidance/proportional_navigation.hpp"

#include <algorithm>

namespace kestrel::guidance {

Eigen::Vector3d pn_acceleration(const ProportionalNavigationConfig& k, double max_speed, const Eigen::Vector3d& p,
                                const Eigen::Vector3d& v, const Eigen::Vector3d& p_t, const Eigen::Vector3d& v_t,
                                const Eigen::Vector3d& a_t) {
  const Eigen::Vector3d r = p_t - p;
  const double range = r.norm();
  if (range < 1e-6) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d los = r / range;
  const Eigen::Vector3d v_r = v_t - v;
  const Eigen::Vector3d omega = r.cross(v_r) / (range * range);
  const double closing = -v_r.dot(los);
  Eigen::Vector3d a = k.navigation_constant * closing * omega.cross(los);
  if (k.augmented) a += 0.5 * k.navigation_constant * (a_t - a_t.dot(los) * los);
  const double wanted_closing = std::min(k.closing_speed_m_s, max_speed);
  a += k.closing_gain_1_s * (wanted_closing - closing) * los;
  return a;
}

ComponentSpec ProportionalNavigation::spec() {
  using C = ProportionalNavigationConfig;
  ConfigSpec<C> c;
  c.param("navigation_constant", &C::navigation_constant)
      .range(0.0, 20.0)
      .describe("N: acceleration per unit of closing speed and line-of-sight rate (3 to 5 usually)");
  c.param("closing_speed_m_s", &C::closing_speed_m_s)
      .with_unit("m/s")
      .range(0.0, 1000.0)
      .describe("closing speed the law accelerates to along the line of sight (at most the top speed)");
  c.param("closing_gain_1_s", &C::closing_gain_1_s)
      .with_unit("1/s")
      .range(0.0, 100.0)
      .describe("k_c: how fast the closing speed is brought to closing_speed_m_s");
  c.param("augmented", &C::augmented).describe("augmented PN: add N/2 times the target's normal acceleration");
  c.param("handover_m", &C::handover_m)
      .with_unit("m")
      .range(0.0, 1000.0)
      .describe("hand over to the terminal phase (align the net, fire) within this distance of the aim pose");
  return ComponentSpec("pn", "True proportional navigation towards the aim pose, with a closing-speed term")
      .details(
          "a = N V_c (omega x r/|r|) + k_c (V_close - V_c) r/|r|, where r runs from the reference to the aim pose, "
          "omega is the line-of-sight rate and V_c the closing speed; the wanted velocity is the reference's plus "
          "a dt. Zero normal command on a collision course. Within handover_m the terminal phase aligns the net.")
      .config(std::move(c));
}

ProportionalNavigation::ProportionalNavigation(const ComponentInit& init)
    : cfg_(init.config<ProportionalNavigationConfig>()) {}

GuidanceCommand ProportionalNavigation::command(const Engagement& e) {
  if (within_handover(e, cfg_.handover_m)) return terminal_phase();
  const Eigen::Vector3d a = pn_acceleration(cfg_, e.limits.max_speed, e.position, e.velocity, e.aim.position,
                                            e.target.velocity, e.target.acceleration);
  return {e.velocity + a * e.dt, e.aim.yaw, false, std::nullopt};
}

}  // namespace kestrel::guidance
