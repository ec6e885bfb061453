#include "kestrel/guidance/fast_response_pn.hpp"

#include <algorithm>

namespace kestrel::guidance {

Eigen::Vector3d frpn_acceleration(const FastResponsePnConfig& k, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                                  const Eigen::Vector3d& p_t, const Eigen::Vector3d& v_t) {
  const Eigen::Vector3d dp = p_t - p;
  const Eigen::Vector3d dv = v_t - v;
  const double speed = dv.norm();
  // Without relative motion the time to go is unbounded: the PN term vanishes, pursuit remains.
  const double t_go = speed > 1e-9 ? std::max(dp.norm() / speed, k.min_time_to_go_s) : 1e9;
  const Eigen::Vector3d linearised_pn = (dp + dv * t_go) / (t_go * t_go);
  return k.gain * ((1.0 - k.pursuit_weight) * linearised_pn + k.pursuit_weight * dp);
}

ComponentSpec FastResponsePn::spec() {
  using C = FastResponsePnConfig;
  ConfigSpec<C> c;
  c.param("gain", &C::gain).range(0.0, 1000.0).describe("G: the overall gain (the paper's 19.7)");
  c.param("pursuit_weight", &C::pursuit_weight)
      .range(0.0, 1.0)
      .describe("W: the share of pure pursuit blended with linearised PN (the paper's 0.051)");
  c.param("min_time_to_go_s", &C::min_time_to_go_s)
      .with_unit("s")
      .range(0.001, 10.0)
      .describe("the time to go |dp| / |dv| never falls below this");
  c.param("handover_m", &C::handover_m)
      .with_unit("m")
      .range(0.0, 1000.0)
      .describe("hand over to the terminal phase (align the net, fire) within this distance of the aim pose");
  return ComponentSpec("frpn", "Fast-response proportional navigation (Pliska et al. 2024) towards the aim pose")
      .details(
          "a = G ((1 - W) (dp + dv t_go) / t_go^2 + W dp), with dp from the reference to the aim pose, dv the "
          "target's velocity relative to the reference's and t_go = |dp| / |dv|; the wanted velocity is the "
          "reference's plus a dt (the reference limits it). Within handover_m the terminal phase aligns the net.")
      .config(std::move(c));
}

FastResponsePn::FastResponsePn(const ComponentInit& init) : cfg_(init.config<FastResponsePnConfig>()) {}

GuidanceCommand FastResponsePn::command(const Engagement& e) {
  if (within_handover(e, cfg_.handover_m)) return terminal_phase();
  const Eigen::Vector3d a = frpn_acceleration(cfg_, e.position, e.velocity, e.aim.position, e.target.velocity);
  return {e.velocity + a * e.dt, e.aim.yaw, false, std::nullopt};
}

}  // namespace kestrel::guidance
