#include "detection_scoring.hpp"

#include "kestrel/algorithms/assignment.hpp"

namespace kestrel::evaluation {

FrameScore DetectionScorer::add_frame(double capture_s, double arrival_s,
                                      const std::vector<Eigen::Vector3d>& detections,
                                      const std::vector<TruthObject>& truth) {
  FrameScore score;
  score.capture_s = capture_s;
  if (capture_s < skip_) {
    score.scored = false;
    return score;
  }
  Eigen::MatrixXd cost(static_cast<Eigen::Index>(detections.size()), static_cast<Eigen::Index>(truth.size()));
  for (std::size_t d = 0; d < detections.size(); ++d)
    for (std::size_t t = 0; t < truth.size(); ++t)
      cost(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(t)) = (detections[d] - truth[t].position).norm();
  const auto assignment = algorithms::solve_assignment(cost, radius_);

  for (std::size_t d = 0; d < detections.size(); ++d) {
    const int t = assignment.row_to_col[d];
    if (t < 0) {
      ++score.fp;
      continue;
    }
    ++score.tp;
    const Eigen::Vector3d error = detections[d] - truth[static_cast<std::size_t>(t)].position;
    score.matches.push_back({static_cast<int>(d), t, error});
    sum_sq_ += error.cwiseProduct(error);
    sum_ += error;
  }
  for (std::size_t t = 0; t < truth.size(); ++t)
    if (assignment.col_to_row[t] < 0 && truth[t].in_view) ++score.fn;

  // The lag follows one object: the first one seen.
  if (!lag_object_ && !truth.empty()) lag_object_ = truth.front().id;
  for (std::size_t t = 0; t < truth.size(); ++t) {
    if (truth[t].id != lag_object_) continue;
    truth_curve_.push_back({capture_s, truth[t].position});
    if (const int d = assignment.col_to_row[t]; d >= 0)
      measured_curve_.push_back({arrival_s, detections[static_cast<std::size_t>(d)]});
  }

  ++frames_;
  tp_ += static_cast<std::uint64_t>(score.tp);
  fp_ += static_cast<std::uint64_t>(score.fp);
  fn_ += static_cast<std::uint64_t>(score.fn);
  return score;
}

DetectionSummary DetectionScorer::summary(double max_lag_s, double lag_step_s) const {
  DetectionSummary s;
  s.frames = frames_;
  s.tp = tp_;
  s.fp = fp_;
  s.fn = fn_;
  if (tp_ + fp_ > 0) s.precision = static_cast<double>(tp_) / static_cast<double>(tp_ + fp_);
  if (tp_ + fn_ > 0) s.recall = static_cast<double>(tp_) / static_cast<double>(tp_ + fn_);
  if (tp_ > 0) {
    s.rmse = Eigen::Vector3d((sum_sq_ / static_cast<double>(tp_)).cwiseSqrt());
    s.mean_error = Eigen::Vector3d(sum_ / static_cast<double>(tp_));
  }
  s.lag_s = algorithms::estimate_lag(truth_curve_, measured_curve_, max_lag_s, lag_step_s);
  return s;
}

}  // namespace kestrel::evaluation
