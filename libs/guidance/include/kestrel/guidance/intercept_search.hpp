#pragma once
// `intercept_search`: a receding-horizon plan over the target's sampled futures. Each frame it
// searches launch times within its horizon and closing speeds along the line of sight; for each
// it places the launch where the net, inheriting the hunter's velocity, opens on the futures' mean,
// checks that the hunter reaches that point at that velocity, level, within its limits (the
// least-jerk path from its state) and with the target in the camera's view all along, and counts the share of the
// futures the open net would hold, the hunter's own error in getting there drawn per path. It flies the best candidate,
// its chance discounted for the wait, towards its launch point, and reports that value for the fire policy to weigh a
// shot now against. The launch it flies is kept, its time counting down, while it is worth nearly as much as the best
// new one: a plan chosen afresh every frame would never arrive (its first acceleration is the path's gentlest). Nothing
// in it is keyed to a kind of flight: a turn, a stop or a dash is in the futures.
#include <Eigen/Core>
#include <vector>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/guidance/capture_chance.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/guidance/quintic.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct InterceptSearchConfig {
  double horizon_s = 2.5;              ///< latest launch planned for
  double step_s = 0.1;                 ///< launch times searched
  double max_closing_speed_m_s = 6.0;  ///< fastest run-in along the line of sight at the launch
  std::int64_t closing_speeds = 3;     ///< closing speeds searched, 0 to the fastest
  double acceleration_share = 0.8;     ///< of the limit, for a new plan (the rest corrects it)
  double execution_error_m = 0.15;     ///< the hunter's error at a launch planned for now
  double execution_error_m_s = 0.05;   ///< and its growth per second of plan
  double max_look_away_deg = 35.0;     ///< the heading stays this near the target's bearing
  double view_half_width_deg = 40.0;   ///< the target stays this near the optical axis, sideways,
  double view_half_height_deg = 32.0;  ///< and up or down, along the path (the camera's view less a margin)
  double view_range_m = 14.0;          ///< and no farther
  double min_range_m = 1.8;            ///< nor nearer: the camera loses it, and the hunter may hit it
  double hazard_time_s = 2.0;          ///< a launch tau later is worth exp(-tau / this) as much
  double gain_1_s = 1.5;               ///< pull towards a launch point planned within min_plan_s
  double min_plan_s = 0.3;             ///< nearer launches are held, not flown to on a path
  double keep_share = 0.8;             ///< the launch flown is kept while worth this share of the best
  double standoff_belief = 0.5;        ///< a target this likely to react to the hunter is waited for
  double standoff_value = 0.25;        ///< beyond its reaction radius while no launch is worth this
  double standoff_margin_m = 5.0;      ///< that far beyond the radius (room to run in)
  double standoff_height_m = 1.0;      ///< above the target
  std::int64_t seed = 7;               ///< the hunter's errors drawn per path
};

/// One candidate: a launch tau seconds ahead, from `point` moving at `velocity`, heading `yaw`.
struct LaunchPlan {
  double time_s = 0.0;
  double closing_m_s = 0.0;                            ///< along the line of approach, beyond the target's
  Eigen::Vector2d line = Eigen::Vector2d::UnitX();     ///< the line of approach (horizontal, unit)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     ///< the hunter (body) then, world
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< world
  double yaw = 0.0;
  Quintic path;  ///< from the hunter's reference to the launch
  CaptureChance chance;
  double value = 0.0;  ///< the chance discounted for the wait
};

class InterceptSearch final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit InterceptSearch(const ComponentInit& init);
  explicit InterceptSearch(InterceptSearchConfig config);
  GuidanceCommand command(const Engagement& e) override;
  bool needs_futures() const override { return true; }
  /// The best candidate of the last command, if any was reachable.
  const std::optional<LaunchPlan>& plan() const { return plan_; }
  void reset() override { plan_.reset(); }

 private:
  /// A launch tau ahead at this closing speed, along `line` (none: the line of sight then, a new
  /// plan; given: the launch already flown, which may use the whole acceleration limit).
  std::optional<LaunchPlan> candidate(const Engagement& e, double tau, double closing,
                                      const std::optional<Eigen::Vector2d>& line = std::nullopt) const;

  /// Waiting beyond the reaction radius of a target that reacts to the hunter, facing it, its
  /// velocity fed forward.
  GuidanceCommand standoff(const Engagement& e) const;

  /// Whether a hunter at `hunter`, accelerating so and facing the target, sees it in its camera.
  bool in_view(const Eigen::Vector3d& hunter, const Eigen::Vector3d& acceleration, const Eigen::Vector3d& target,
               const Eigen::Vector3d& camera_offset) const;

  InterceptSearchConfig cfg_;
  std::vector<Eigen::Vector3d> unit_errors_;  // standard normal draws, one per path
  std::optional<LaunchPlan> plan_;
};

}  // namespace kestrel::guidance
