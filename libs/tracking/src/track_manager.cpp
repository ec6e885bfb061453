#include "kestrel/tracking/track_manager.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

TrackManager::TrackManager(TrackerParts parts) : parts_(std::move(parts)) {
  if (!parts_.filter) throw Error("a tracker needs a filter");
  if (!parts_.associator) throw Error("a tracker needs an associator");
  if (!parts_.initiator) throw Error("a tracker needs an initiator");
  if (!parts_.deleter) throw Error("a tracker needs a deleter");
  if (!parts_.selector) throw Error("a tracker needs a selector");
}

void TrackManager::start_track(const Eigen::Vector3d& detection) {
  Track t{TrackStatus{next_id_++, 1, 1, 0, false, nullptr}, parts_.filter->start(detection), detection};
  t.status.filter = t.filter.get();
  t.status.confirmed = parts_.initiator->confirms(t.status);
  ++counts_.tracks_started;
  counts_.tracks_confirmed += t.status.confirmed;
  tracks_.push_back(std::move(t));
}

msg::Tracks TrackManager::step(Time stamp, const std::vector<Eigen::Vector3d>& detections) {
  if (last_stamp_ && stamp < *last_stamp_)
    throw Error(fmt::format("detections went back in time: a frame captured at {:.6f} s came after one at {:.6f} s",
                            to_seconds(stamp), to_seconds(*last_stamp_)));
  const double dt = last_stamp_ ? to_seconds(stamp - *last_stamp_) : 0.0;
  last_stamp_ = stamp;
  ++counts_.frames;
  counts_.empty_frames += detections.empty();

  // Predict to this frame, then associate.
  std::vector<PredictedMeasurement> predicted;
  predicted.reserve(tracks_.size());
  for (auto& t : tracks_) {
    if (dt > 0) t.filter->predict(dt);
    predicted.push_back(t.filter->predicted_measurement());
  }
  const algorithms::Assignment a = parts_.associator->associate(predicted, detections);

  // Update the tracks that were given a detection; count the misses of the others.
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    TrackStatus& s = tracks_[i].status;
    ++s.age;
    if (const int d = a.row_to_col[i]; d >= 0) {
      tracks_[i].filter->update(detections[static_cast<std::size_t>(d)]);
      tracks_[i].detection = detections[static_cast<std::size_t>(d)];
      ++s.hits;
      s.misses = 0;
    } else {
      ++s.misses;
    }
    if (!s.confirmed && parts_.initiator->confirms(s)) {
      s.confirmed = true;
      ++counts_.tracks_confirmed;
    }
  }
  // A tentative track's end is the initiator's call, a confirmed one's the deleter's.
  std::erase_if(tracks_, [&](const Track& t) {
    return t.status.confirmed ? parts_.deleter->deletes(t.status) : parts_.initiator->drops(t.status);
  });

  std::vector<std::size_t> unclaimed;
  for (std::size_t d = 0; d < detections.size(); ++d)
    if (a.col_to_row[d] < 0) unclaimed.push_back(d);
  for (const std::size_t d : parts_.initiator->initiate(detections, unclaimed)) start_track(detections.at(d));

  // Publish the confirmed tracks; the target is chosen among them.
  msg::Tracks out;
  out.stamp = stamp;
  std::vector<TrackStatus> confirmed;
  for (const auto& t : tracks_) {
    if (!t.status.confirmed) continue;
    confirmed.push_back(t.status);
    msg::Track m;
    m.id = t.status.id;
    m.age = t.status.age;
    m.hits = t.status.hits;
    m.misses = t.status.misses;
    m.state = t.filter->state();
    m.covariance = t.filter->covariance();
    if (t.status.misses == 0) m.detection = t.detection;
    out.items.push_back(std::move(m));
  }
  out.selected_id = parts_.selector->select(confirmed);
  if (const msg::Track* target = out.selected(); target && target->misses > 0) ++counts_.target_coasted_frames;
  return out;
}

}  // namespace kestrel::tracking
