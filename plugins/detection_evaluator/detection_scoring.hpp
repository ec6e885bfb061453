#pragma once
// Scores detections against ground truth frame by frame: Hungarian matching within a gate,
// true/false positives and misses, per-axis RMSE of matched detections, and the detection lag by
// cross-correlation (paper, sections 2.2 and 3.1-3.2).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "kestrel/algorithms/lag.hpp"

namespace kestrel::evaluation {

struct TruthObject {
  std::uint64_t id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< camera frame
  bool in_view = true;
};

struct Match {
  int detection = -1;
  int truth = -1;
  Eigen::Vector3d error = Eigen::Vector3d::Zero();  ///< detection - truth
};

struct FrameScore {
  bool scored = true;  ///< false for a frame captured before skip_first_s: nothing counted
  double capture_s = 0.0;
  int tp = 0, fp = 0, fn = 0;
  std::vector<Match> matches;
};

struct DetectionSummary {
  std::uint64_t frames = 0;
  std::uint64_t tp = 0, fp = 0, fn = 0;
  // Each is undefined (empty) when there is nothing to measure it on, rather than a flattering
  // convention: no detections, nothing to find, no matches, curves too short to correlate.
  std::optional<double> precision;            ///< TP / (TP + FP); undefined without detections
  std::optional<double> recall;               ///< TP / (TP + FN); undefined with nothing to find
  std::optional<Eigen::Vector3d> rmse;        ///< per camera axis, over matches; undefined without
  std::optional<Eigen::Vector3d> mean_error;  ///< bias of matched detections; undefined without
  std::optional<double> lag_s;
};

class DetectionScorer {
 public:
  /// Frames captured before `skip_first_s` are not scored (the chain settling in).
  explicit DetectionScorer(double match_radius_m, double skip_first_s = 0.0)
      : radius_(match_radius_m), skip_(skip_first_s) {}

  /// Scores one frame. `arrival_s` is when the detections were available (the lag's time base).
  /// A truth object out of view is not a miss when undetected, but matching it is a hit.
  /// A frame captured before skip_first_s changes nothing and comes back with `scored` false.
  FrameScore add_frame(double capture_s, double arrival_s, const std::vector<Eigen::Vector3d>& detections,
                       const std::vector<TruthObject>& truth);

  DetectionSummary summary(double max_lag_s = 1.0, double lag_step_s = 0.001) const;

 private:
  double radius_;
  double skip_;
  std::uint64_t frames_ = 0, tp_ = 0, fp_ = 0, fn_ = 0;
  Eigen::Vector3d sum_sq_ = Eigen::Vector3d::Zero(), sum_ = Eigen::Vector3d::Zero();
  std::vector<algorithms::TimedPoint> truth_curve_;     // first truth object, at capture times
  std::vector<algorithms::TimedPoint> measured_curve_;  // its matched detections, at arrival times
  std::optional<std::uint64_t> lag_object_;
};

}  // namespace kestrel::evaluation
