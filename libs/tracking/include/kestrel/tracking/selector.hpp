#pragma once
// The selector: which confirmed track is the target to aim at.
//
// Every selector ranks the candidates by one score and takes the best; a tie goes to the
// candidate that comes first, which is the oldest track (lowest id), so that the target does not
// move between equally good tracks.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kestrel/component.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/track_status.hpp"

namespace kestrel::tracking {

class Selector {
 public:
  static constexpr std::string_view kKind = "selector";
  virtual ~Selector() = default;
  /// The target's id among `confirmed` (in order of birth, oldest first); empty if none.
  virtual std::optional<std::uint64_t> select(const std::vector<TrackStatus>& confirmed) const = 0;
};

/// A selector that takes the track of highest score(); ties go to the oldest.
class ScoreSelector : public Selector {
 public:
  std::optional<std::uint64_t> select(const std::vector<TrackStatus>& confirmed) const final;

 protected:
  /// Higher is better.
  virtual double score(const TrackStatus& track) const = 0;
};

/// The paper's rule: the track that has lived longest (noise tracks are short-lived).
class LongestLivingSelector final : public ScoreSelector {
 public:
  static ComponentSpec spec();
  explicit LongestLivingSelector(const ComponentInit&) {}
  LongestLivingSelector() = default;

 private:
  double score(const TrackStatus& track) const override;
};

/// The track with the most associated detections.
class MostHitsSelector final : public ScoreSelector {
 public:
  static ComponentSpec spec();
  explicit MostHitsSelector(const ComponentInit&) {}
  MostHitsSelector() = default;

 private:
  double score(const TrackStatus& track) const override;
};

/// The track closest to the sensor (the origin of the detections' frame).
class NearestSelector final : public ScoreSelector {
 public:
  static ComponentSpec spec();
  explicit NearestSelector(const ComponentInit&) {}
  NearestSelector() = default;

 private:
  double score(const TrackStatus& track) const override;
};

/// The most confident track: the smallest trace of its position covariance.
class MostConfidentSelector final : public ScoreSelector {
 public:
  static ComponentSpec spec();
  explicit MostConfidentSelector(const ComponentInit&) {}
  MostConfidentSelector() = default;

 private:
  double score(const TrackStatus& track) const override;
};

}  // namespace kestrel::tracking
