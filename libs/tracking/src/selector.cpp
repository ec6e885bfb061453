#include "kestrel/tracking/selector.hpp"

#include "kestrel/error.hpp"
#include "kestrel/tracking/filter.hpp"

namespace kestrel::tracking {

std::optional<std::uint64_t> ScoreSelector::select(const std::vector<TrackStatus>& confirmed) const {
  const TrackStatus* best = nullptr;
  double best_score = 0.0;
  for (const auto& t : confirmed) {
    const double s = score(t);
    if (!best || s > best_score) {  // strictly better: a tie keeps the earlier, older track
      best = &t;
      best_score = s;
    }
  }
  if (!best) return std::nullopt;
  return best->id;
}

namespace {
constexpr const char* kTieRule = " A tie goes to the oldest track (the lowest id).";
}

ComponentSpec LongestLivingSelector::spec() {
  return ComponentSpec("longest_living", "The track that has lived longest (the paper's rule)")
      .details(std::string("Noise tracks are short-lived, so the oldest track is the intruder (paper, section 2.3).") +
               kTieRule);
}
double LongestLivingSelector::score(const TrackStatus& t) const { return t.age; }

ComponentSpec MostHitsSelector::spec() {
  return ComponentSpec("most_hits", "The track with the most associated detections")
      .details(std::string("Unlike the age, hits do not grow while a track coasts through misses.") + kTieRule);
}
double MostHitsSelector::score(const TrackStatus& t) const { return t.hits; }

ComponentSpec NearestSelector::spec() {
  return ComponentSpec("nearest", "The track closest to the camera")
      .details(std::string("Distance of the track's expected position from the origin of the detections' frame.") +
               kTieRule);
}
double NearestSelector::score(const TrackStatus& t) const { return -t.filter->predicted_measurement().position.norm(); }

ComponentSpec MostConfidentSelector::spec() {
  return ComponentSpec("most_confident", "The track whose position is most certain")
      .details(std::string("The smallest trace of the position covariance (the top-left 3x3 block of the "
                           "filter's covariance): a track that coasts, or was just born, is uncertain.") +
               kTieRule);
}
double MostConfidentSelector::score(const TrackStatus& t) const {
  return -t.filter->covariance().topLeftCorner<3, 3>().trace();
}

}  // namespace kestrel::tracking
