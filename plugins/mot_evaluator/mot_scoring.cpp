#include "mot_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kestrel/algorithms/assignment.hpp"

namespace kestrel::evaluation {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Distances within the match radius; the rest "may not match" (NaN).
double within(double distance, double radius) {
  return distance <= radius ? distance : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

double TargetScore::mota() const {
  if (frames == 0) return 0.0;
  return 1.0 - static_cast<double>(missing + off + switches) / static_cast<double>(frames);
}

// Intruders out of the camera's view cannot be seen: like MOTChallenge's distractors they are
// neither missed nor found, and a track that follows one (coasting out of view) is set aside
// rather than counted as a false positive. Which tracks follow them is decided by one
// assignment of every track to every intruder, as py-motmetrics' MOT16 preprocessing does.
std::vector<bool> TrackingScorer::set_aside(const msg::Tracks& tracks, const msg::GroundTruth& truth) const {
  std::vector<bool> aside(tracks.items.size(), false);
  const bool any_hidden =
      std::any_of(truth.objects.begin(), truth.objects.end(), [](const auto& o) { return !o.in_view; });
  if (!any_hidden || tracks.items.empty()) return aside;
  Eigen::MatrixXd cost(static_cast<Eigen::Index>(truth.objects.size()), static_cast<Eigen::Index>(tracks.items.size()));
  for (std::size_t i = 0; i < truth.objects.size(); ++i)
    for (std::size_t j = 0; j < tracks.items.size(); ++j) {
      const double d = (truth.objects[i].position_camera - tracks.items[j].position()).norm();
      cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = d <= radius_ ? d : kInfinity;
    }
  const auto a = algorithms::solve_assignment(cost, radius_);
  for (std::size_t i = 0; i < truth.objects.size(); ++i)
    if (const int j = a.row_to_col[i]; j >= 0 && !truth.objects[i].in_view) aside[static_cast<std::size_t>(j)] = true;
  return aside;
}

bool TrackingScorer::add_frame(const msg::Tracks& tracks, const msg::GroundTruth& truth, double arrival_s) {
  if (to_seconds(truth.stamp) < skip_) return false;
  std::vector<const msg::GroundTruthObject*> visible;
  for (const auto& o : truth.objects)
    if (o.in_view) visible.push_back(&o);
  const std::vector<bool> aside = set_aside(tracks, truth);
  std::vector<const msg::Track*> scored;
  for (std::size_t j = 0; j < tracks.items.size(); ++j)
    if (!aside[j]) scored.push_back(&tracks.items[j]);

  std::vector<std::uint64_t> objects, hypotheses;
  for (const auto* o : visible) objects.push_back(o->id);
  for (const auto* t : scored) hypotheses.push_back(t->id);
  Eigen::MatrixXd d(static_cast<Eigen::Index>(objects.size()), static_cast<Eigen::Index>(hypotheses.size()));
  for (std::size_t i = 0; i < visible.size(); ++i)
    for (std::size_t j = 0; j < scored.size(); ++j)
      d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          within((visible[i]->position_camera - scored[j]->position()).norm(), radius_);
  mot_.update(objects, hypotheses, d);

  const msg::Track* selected = tracks.selected();
  score_target(truth, selected);

  // The selected track against the object it is matched to this frame; the lag on the first
  // object's curve.
  if (!truth.objects.empty()) truth_curve_.push_back({to_seconds(truth.stamp), truth.objects.front().position_camera});
  if (!selected) return true;
  for (const auto& [i, j] : mot_.last_matches()) {
    if (scored[static_cast<std::size_t>(j)]->id != selected->id) continue;
    const msg::GroundTruthObject& object = *visible[static_cast<std::size_t>(i)];
    const Eigen::Vector3d e = selected->position() - object.position_camera;
    selected_sq_ += e.cwiseProduct(e);
    selected_sum_ += e;
    ++selected_samples_;
    if (object.id == truth.objects.front().id) selected_curve_.push_back({arrival_s, selected->position()});
  }
  return true;
}

// Frames count when an intruder is in view. A target near an intruder is on target (one out of
// view included: the track coasts on it); near none, off target.
void TrackingScorer::score_target(const msg::GroundTruth& truth, const msg::Track* selected) {
  const bool any_visible =
      std::any_of(truth.objects.begin(), truth.objects.end(), [](const auto& o) { return o.in_view; });
  if (any_visible) ++target_.frames;
  if (!selected) {
    if (any_visible) ++target_.missing;
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
  if (!any_visible) return;  // no intruder in view: the frame does not count
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
    s.bias_axes = selected_sum_ / n;
    s.rmse = std::sqrt(selected_sq_.sum() / n);
  }
  s.lag_s = algorithms::estimate_lag(truth_curve_, selected_curve_, max_lag_s, lag_step_s);
  s.target = target_;
  return s;
}

}  // namespace kestrel::evaluation
