#pragma once
// `frpn`: fast-response proportional navigation (Pliska, Vrba, Báča, Saska, "Towards Safe
// Mid-Air Drone Interception: Strategies for Tracking & Capture", IEEE RA-L 2024, eq. 19), in
// Cartesian form, towards the aim pose:
//
//   dp = p_aim - p,  dv = v_target - v,  t_go = |dp| / |dv|   (at least min_time_to_go_s)
//   a = G ((1 - W) (dp + dv t_go) / t_go^2 + W dp)
//
// The first term is linearised PN: the zero-effort miss dp + dv t_go, nulled over the time to go.
// The second, a small share W of pure pursuit, keeps the hunter moving when the relative velocity
// is small (a hovering hunter and a slow target give a long t_go and almost no PN command). The
// large gain G saturates the command at the hunter's acceleration limit most of the time: the law
// responds at once, which is its point. Its weaknesses: t_go = |dp| / |dv| is right only when the
// relative velocity points along the line of sight (a crossing target gets too long a t_go), and
// at full gain it passes the estimate's noise straight to the hunter's acceleration.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct FastResponsePnConfig {
  double gain = 19.7;             ///< G (the paper's)
  double pursuit_weight = 0.051;  ///< W (the paper's)
  double min_time_to_go_s = 0.1;  ///< t_go never below this (dp and dv both vanish at the end)
  double handover_m = 2.0;        ///< terminal phase within this distance of the aim pose
};

/// The FRPN acceleration for a pursuer at (p, v) and a point at (p_t, v_t).
Eigen::Vector3d frpn_acceleration(const FastResponsePnConfig& config, const Eigen::Vector3d& p,
                                  const Eigen::Vector3d& v, const Eigen::Vector3d& p_t, const Eigen::Vector3d& v_t);

class FastResponsePn final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit FastResponsePn(const ComponentInit& init);
  explicit FastResponsePn(FastResponsePnConfig config) : cfg_(config) {}
  GuidanceCommand command(const Engagement& e) override;

 private:
  FastResponsePnConfig cfg_;
};

}  // namespace kestrel::guidance
