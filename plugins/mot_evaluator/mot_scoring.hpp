#pragma once
// Scores tracks against ground truth frame by frame: CLEAR-MOT and IDF1 over every published
// track (MOT16, py-motmetrics), the selected track's RMSE and lag, and the selected track alone
// as the aiming sees it (on an intruder, on nothing, missing, switching between intruders).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "kestrel/algorithms/clear_mot.hpp"
#include "kestrel/algorithms/lag.hpp"
#include "kestrel/messages/ground_truth.hpp"
#include "kestrel/messages/tracks.hpp"

namespace kestrel::evaluation {

/// The selected target, frame by frame.
struct TargetScore {
  std::uint64_t frames = 0;    ///< frames with at least one intruder in view
  std::uint64_t on = 0;        ///< the target is within the match radius of an intruder
  std::uint64_t off = 0;       ///< a target is selected but no intruder is near it
  std::uint64_t missing = 0;   ///< an intruder is there but no target is selected
  std::uint64_t switches = 0;  ///< the target moved from one intruder to another
  /// 1 - (missing + off + switches) / frames: MOTA with the target as the only hypothesis.
  double mota() const;
};

struct TrackingSummary {
  algorithms::MotSummary mot;
  Eigen::Vector3d rmse_axes = Eigen::Vector3d::Zero();  ///< selected track, per axis
  Eigen::Vector3d bias_axes = Eigen::Vector3d::Zero();  ///< selected track, mean error per axis
  double rmse = 0.0;                                    ///< selected track, 3D
  std::uint64_t selected_frames = 0;                    ///< frames the selected track matched an object
  std::optional<double> lag_s;
  TargetScore target;
};

class TrackingScorer {
 public:
  /// Frames captured before `skip_first_s` are not scored (the tracker settling in).
  explicit TrackingScorer(double match_radius_m, double skip_first_s = 0.0)
      : radius_(match_radius_m), skip_(skip_first_s) {}

  /// One frame. `arrival_s` is when the tracks were available (the lag's time base). Objects out
  /// of view are neither missed nor found, and a track on one is not a false positive. Returns
  /// false, changing nothing, for a frame captured before skip_first_s.
  bool add_frame(const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival_s);

  TrackingSummary summary(double max_lag_s = 1.0, double lag_step_s = 0.001) const;

 private:
  std::vector<bool> set_aside(const msg::Tracks& tracks, const msg::GroundTruth& truth) const;
  void score_target(const msg::GroundTruth& truth, const msg::Track* selected);

  double radius_;
  double skip_;
  algorithms::ClearMotAccumulator mot_;
  Eigen::Vector3d selected_sq_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d selected_sum_ = Eigen::Vector3d::Zero();
  std::uint64_t selected_samples_ = 0;
  std::vector<algorithms::TimedPoint> truth_curve_, selected_curve_;
  TargetScore target_;
  std::optional<std::uint64_t> target_object_;  // the intruder the target was last on
};

}  // namespace kestrel::evaluation
