#pragma once
// `pn`: true proportional navigation (Zarchan, "Tactical and Strategic Missile Guidance", ch. 2),
// in three dimensions, towards the aim pose (the point the hunter must reach, moving with the
// target):
//
//   r = p_aim - p,  v_r = v_target - v,  omega = (r x v_r) / |r|^2   (line-of-sight rate)
//   V_c = -(r . v_r) / |r|                                            (closing speed)
//   a_PN = N V_c (omega x r/|r|)                                      (normal to the line of sight)
//
// A missile has thrust along its path; a multirotor starting from a hover does not close by
// itself, so the law adds an acceleration along the line of sight that brings the closing speed
// to `closing_speed_m_s` (at most the hunter's top speed): a_c = k_c (V_close - V_c) r/|r|.
// With `augmented`, the target's acceleration normal to the line of sight is added with N/2
// (augmented PN). On a collision course the line of sight does not turn, and PN commands nothing
// across it. Its weakness: it reacts to the line of sight's rate, which noise and a target's
// manoeuvre make, so it responds late to a jink and amplifies noise at short range.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct ProportionalNavigationConfig {
  double navigation_constant = 4.0;  ///< N, usually 3 to 5
  double closing_speed_m_s = 100.0;  ///< wanted closing speed (limited by the hunter's top speed)
  double closing_gain_1_s = 2.0;     ///< k_c
  bool augmented = false;            ///< add N/2 times the target's normal acceleration
  double handover_m = 2.0;           ///< terminal phase within this distance of the aim pose
};

/// The PN acceleration (normal to the line of sight, plus the closing term) for a pursuer at
/// (p, v) and a point at (p_t, v_t) accelerating at a_t.
Eigen::Vector3d pn_acceleration(const ProportionalNavigationConfig& config, double max_speed, const Eigen::Vector3d& p,
                                const Eigen::Vector3d& v, const Eigen::Vector3d& p_t, const Eigen::Vector3d& v_t,
                                const Eigen::Vector3d& a_t);

class ProportionalNavigation final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit ProportionalNavigation(const ComponentInit& init);
  explicit ProportionalNavigation(ProportionalNavigationConfig config) : cfg_(config) {}
  GuidanceCommand command(const Engagement& e) override;

 private:
  ProportionalNavigationConfig cfg_;
};

}  // namespace kestrel::guidance
