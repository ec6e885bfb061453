#pragma once
// The chance that a net launched at a given time, pose and velocity holds the target, counted on
// the target's sampled futures: the share of paths that come within the net's radius of its
// centre while it is open. The planner scores its candidate launches with it, and the fire policy
// the launch it could make now, so both read the same futures.
#include <Eigen/Core>
#include <kestrel/geometry/frames.hpp>
#include <vector>

#include "kestrel/guidance/reaction.hpp"
#include "kestrel/guidance/target_futures.hpp"
#include "kestrel/net/net_model.hpp"

namespace kestrel::guidance {

/// A launch: when (s from the futures' time origin), from where the launcher (camera) is and how
/// it moves; the net inherits that velocity.
struct Launch {
  double time_s = 0.0;
  geometry::CameraPose launcher;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
};

struct CaptureChance {
  double probability = 0.0;  ///< share of the paths the open net holds
  /// mean over the paths of exp(-d^2 / (2 (2 r)^2)), d the least distance while open: how near
  /// the launch comes when it would not catch (the planner's tie-break far from any capture).
  double closeness = 0.0;
};

/// The launch against every path. `launcher_errors` (none, or one per path, world metres) moves
/// the launcher for that path: the hunter's error in flying to the launch point.
/// `seen_at_launch`: a launch later than now is aimed then, with the target seen where it is: each
/// path counts from where it is at the launch (its offset from the paths' mean there taken out), so
/// only how it moves on can make it escape. (Taking its velocity's offset out as well made the
/// planner bolder and the engagements worse: docs/experiments.) False: the launch is aimed now, on
/// where the paths are expected (a shot now, or a launch committed to now).
CaptureChance capture_chance(const TargetFutures& futures, const net::NetModel& net, const Launch& launch,
                             const std::vector<Eigen::Vector3d>& launcher_errors = {}, bool seen_at_launch = false);

/// The hypothesis that the target reacts to the hunter (reaction.hpp), for a launch's chance: its
/// weight, its model, and where the hunter flies until and after the launch.
struct ReactingTarget {
  double probability = 0.0;
  const ReactionConfig* config = nullptr;
  HunterPath hunter;
};

/// The chance over both hypotheses: the futures as drawn, and as they would be reacting to the
/// hunter's path, weighed by the reacting hypothesis's probability.
CaptureChance capture_chance(const TargetFutures& futures, const net::NetModel& net, const Launch& launch,
                             const ReactingTarget& reacting, const std::vector<Eigen::Vector3d>& launcher_errors = {},
                             bool seen_at_launch = false);

}  // namespace kestrel::guidance
