#include "mot_scoring.hpp"

#include <cmath>
#include <limits>

namespace kestrel::evaluation {

double TargetScore::mota() const {
  if (frames == 0) return 0.0;
  return 1.0 - static_cast<double>(missing + off + switches) / static_cast<double>(frames);
}

void TrackingScorer::add_frame(const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival_s) {
  std::vector<std::uint64_t> objects, hypotheses;
  for (const auto& o : truth.objects) objects.push_back(o.id);
  for (const auto& t : tracks.items) hypotheses.push_back(t.id);
  Eigen::MatrixXd d(static_cast<Eigen::Index>(objects.size()), static_cast<Eigen::Index>(hypotheses.size()));
  for (std::size_t i = 0; i < objects.size(); ++i)
    for (std::size_t j = 0; j < hypotheses.size(); ++j) {
      const double v = (truth.objects[i].position_camera - tracks.items[j].position()).norm();
      d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          v <= radius_ ? v : std::numeric_limits<double>::quiet_NaN();
    }
  mot_.update(objects, hypotheses, d);

  const msg::Track* selected = tracks.selected();
  score_target(truth, selected);

  // The selected track against the object it is matched to this frame.
  if (!truth.objects.empty()) truth_curve_.push_back({to_seconds(truth.stamp), truth.objects.front().position_camera});
  if (!selected) return;
  for (const auto& [i, j] : mot_.last_matches()) {
    if (tracks.items[static_cast<std::size_t>(j)].id != selected->id) continue;
    const Eigen::Vector3d e = selected->position() - truth.objects[static_cast<std::size_t>(i)].position_camera;
    selected_sq_ += e.cwiseProduct(e);
    ++selected_samples_;
    if (i == 0) selected_curve_.push_back({arrival_s, selected->position()});
  }
}

void TrackingScorer::score_target(const msg::GroundTruth& truth, const msg::Track* selected) {
  if (!truth.objects.empty()) ++target_.frames;
  if (!selected) {
    if (!truth.objects.empty()) ++target_.missing;
    return;
  }
  const msg::GroundTruthObject* nearest = nullptr;
  double best = radius_;
  for (const auto& o : truth.objects)
    if (const double d = (o.position_camera - selected->position()).norm(); d <= best) {
      best = d;
      nearest = &o;
    }
  if (!nearest) {
    ++target_.off;
    return;
  }
  ++target_.on;
  if (target_object_ && *target_object_ != nearest->id) ++target_.switches;
  target_object_ = nearest->id;
}

TrackingSummary TrackingScorer::summary(double max_lag_s, double lag_step_s) const {
  TrackingSummary s;
  s.mot = mot_.summary();
  s.selected_frames = selected_samples_;
  if (selected_samples_ > 0) {
    const double n = static_cast<double>(selected_samples_);
    s.rmse_axes = (selected_sq_ / n).cwiseSqrt();
    s.rmse = std::sqrt(selected_sq_.sum() / n);
  }
  s.lag_s = algorithms::estimate_lag(truth_curve_, selected_curve_, max_lag_s, lag_step_s);
  s.target = target_;
  return s;
}

}  // namespace kestrel::evaluation
