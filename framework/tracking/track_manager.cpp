#include "kestrel/tracking/track_manager.hpp"

#include <algorithm>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

Selection parse_selection(const std::string& name) {
  if (name == "longest_living") return Selection::longest_living;
  if (name == "most_hits") return Selection::most_hits;
  if (name == "nearest") return Selection::nearest;
  throw Error("unknown target selection rule '" + name + "'");
}

TrackManager::TrackManager(std::shared_ptr<const Associator> associator, FilterFactory factory,
                           TrackManagerOptions options)
    : associator_(std::move(associator)), factory_(std::move(factory)), options_(options) {
  if (!associator_) throw Error("a tracker needs an associator");
}

msg::Tracks TrackManager::step(Time stamp, const std::vector<Eigen::Vector3d>& detections) {
  const double dt = last_stamp_ ? to_seconds(stamp - *last_stamp_) : 0.0;
  if (dt < 0) throw Error("detections went back in time");
  last_stamp_ = stamp;

  std::vector<PredictedMeasurement> predicted;
  for (auto& t : tracks_) {
    if (dt > 0) t.filter->predict(dt);
    predicted.push_back(t.filter->predicted_measurement());
  }
  const algorithms::Assignment a = associator_->associate(predicted, detections);

  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    Track& t = tracks_[i];
    ++t.age;
    if (const int d = a.row_to_col[i]; d >= 0) {
      t.filter->update(detections[static_cast<std::size_t>(d)]);
      ++t.hits;
      t.misses = 0;
      if (t.hits >= options_.confirm_hits) t.confirmed = true;
    } else {
      ++t.misses;
    }
  }
  // A tentative track that misses once was noise: it goes at once, so it neither lingers in the
  // association nor is confirmed later by an unrelated detection (SORT, Stone Soup's initiators).
  tracks_.erase(
      std::remove_if(tracks_.begin(), tracks_.end(),
                     [&](const Track& t) { return t.misses > options_.max_misses || (!t.confirmed && t.misses > 0); }),
      tracks_.end());
  for (std::size_t d = 0; d < detections.size(); ++d) {
    if (a.col_to_row[d] >= 0) continue;
    tracks_.push_back(Track{next_id_++, 1, 1, 0, options_.confirm_hits <= 1, factory_(detections[d])});
  }

  msg::Tracks out;
  out.stamp = stamp;
  const Track* best = nullptr;
  for (const auto& t : tracks_) {
    if (!t.confirmed) continue;  // tentative: not published, never the target
    msg::Track m;
    m.id = t.id;
    m.age = t.age;
    m.hits = t.hits;
    m.misses = t.misses;
    m.state = t.filter->state();
    m.covariance = t.filter->covariance();
    out.items.push_back(std::move(m));
    auto better = [&](const Track& x, const Track& y) {  // is x a better target than y?
      switch (options_.selection) {
        case Selection::longest_living:
          return x.age > y.age;
        case Selection::most_hits:
          return x.hits > y.hits;
        case Selection::nearest:
          return x.filter->predicted_measurement().position.norm() < y.filter->predicted_measurement().position.norm();
      }
      return false;
    };
    if (!best || better(t, *best)) best = &t;  // ties keep the older id
  }
  if (best) out.selected_id = best->id;
  return out;
}

}  // namespace kestrel::tracking
