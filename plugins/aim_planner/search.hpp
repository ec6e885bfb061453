#pragma once
// The search, a component of kind "search": where the hunter goes once it has lost its target
// (nothing seen for the aim's target_timeout_s), until the tracker selects one again.
//
//   hold       hold position and heading (the default)
//   turn       hold position and turn, to the side the target went
//   back_off   back off from where the target was last seen, facing it: from farther away the
//              camera sees more, above and below as well as to the sides; after turn_after_s, turn
//
//   - id: aim
//     type: aim_planner
//     params:
//       search: {type: back_off, distance_m: 5.0}
#include <Eigen/Core>
#include <kestrel/guidance/aim_pose.hpp>
#include <optional>
#include <string_view>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::aim {

/// +1 to turn counter-clockwise (seen from above), -1 clockwise: the side of the hunter's heading
/// `heading_rad` on which `expected_target` (world) lies, from `hunter` (world). Straight ahead
/// or behind, counter-clockwise.
double search_side(double heading_rad, const Eigen::Vector3d& hunter, const Eigen::Vector3d& expected_target);

/// The target's last estimate (position and velocity), flown on for `elapsed_s`.
Eigen::Vector3d expected_position(const Eigen::Vector3d& last_position, const Eigen::Vector3d& last_velocity,
                                  double elapsed_s);

/// What the search knows of the lost target, as the loss begins (world).
struct LostTarget {
  Eigen::Vector3d last_position = Eigen::Vector3d::Zero();  ///< the estimate when last seen
  Eigen::Vector3d last_velocity = Eigen::Vector3d::Zero();
  double since_seen_s = 0.0;                         ///< from the last sighting to the loss
  Eigen::Vector3d hunter = Eigen::Vector3d::Zero();  ///< the hunter's position
  double heading_rad = 0.0;                          ///< and heading
  double min_altitude_m = 0.0;                       ///< no pose below this
};

/// Each frame of the loss: a pose to fly to, or (none) hold position and turn at `yaw_rate`.
struct SearchStep {
  std::optional<guidance::AimPose> goal;
  double yaw_rate_rad_s = 0.0;
};

class Search {
 public:
  static constexpr std::string_view kKind = "search";
  virtual ~Search() = default;
  /// The loss begins.
  virtual void begin(const LostTarget& lost) = 0;
  /// `lost_for_s` after it began; `turn_after_s`: the aim's own time to turn, if it has one now.
  virtual SearchStep step(double lost_for_s, std::optional<double> turn_after_s) const = 0;
};

class HoldSearch final : public Search {
 public:
  static ComponentSpec spec();
  explicit HoldSearch(const ComponentInit&) {}
  HoldSearch() = default;
  void begin(const LostTarget&) override {}
  SearchStep step(double, std::optional<double>) const override { return {}; }
};

struct TurnSearchConfig {
  double yaw_rate_deg_s = 20.0;
};

class TurnSearch final : public Search {
 public:
  static ComponentSpec spec();
  explicit TurnSearch(const ComponentInit& init);
  explicit TurnSearch(TurnSearchConfig config) : cfg_(config) {}
  void begin(const LostTarget& lost) override;
  SearchStep step(double lost_for_s, std::optional<double> turn_after_s) const override;

 private:
  TurnSearchConfig cfg_;
  double side_ = 1.0;  // +1 counter-clockwise, -1 clockwise
};

struct BackOffConfig {
  double distance_m = 5.0;
  double height_m = 0.5;
  double turn_after_s = -1.0;  // < 0: hold the standoff
  double yaw_rate_deg_s = 20.0;
};

class BackOffSearch final : public Search {
 public:
  static ComponentSpec spec();
  explicit BackOffSearch(const ComponentInit& init);
  explicit BackOffSearch(BackOffConfig config) : cfg_(config) {}
  void begin(const LostTarget& lost) override;
  SearchStep step(double lost_for_s, std::optional<double> turn_after_s) const override;

 private:
  BackOffConfig cfg_;
  guidance::AimPose standoff_;
  double side_ = 1.0;
};

}  // namespace kestrel::aim
