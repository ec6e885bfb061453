#pragma once
// The one multi-target tracking loop (paper, section 2.3), composed from swappable components as
// Stone Soup composes its trackers: each frame, predict every track to the frame's time, let the
// associator pair tracks with detections, update the paired tracks, let the initiator confirm or
// drop tentative tracks and the deleter end confirmed ones, start the tracks the initiator asks
// for, and let the selector choose the target among the confirmed tracks.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "kestrel/messages/tracks.hpp"
#include "kestrel/time.hpp"
#include "kestrel/tracking/associator.hpp"
#include "kestrel/tracking/deleter.hpp"
#include "kestrel/tracking/filter.hpp"
#include "kestrel/tracking/initiator.hpp"
#include "kestrel/tracking/selector.hpp"
#include "kestrel/tracking/track_status.hpp"

namespace kestrel::tracking {

/// The components a tracker is made of. Every one is required.
struct TrackerParts {
  std::shared_ptr<Filter> filter;
  std::shared_ptr<const Associator> associator;
  std::shared_ptr<const Initiator> initiator;
  std::shared_ptr<const Deleter> deleter;
  std::shared_ptr<const Selector> selector;
};

/// What a tracker did over a run, for its report.
struct TrackerCounts {
  std::uint64_t frames = 0;
  std::uint64_t empty_frames = 0;    ///< frames without a detection
  std::uint64_t tracks_started = 0;  ///< tentative tracks born
  std::uint64_t tracks_confirmed = 0;
  std::uint64_t target_coasted_frames = 0;  ///< frames whose target had no detection
};

class TrackManager {
 public:
  /// Throws kestrel::Error if a part is missing.
  explicit TrackManager(TrackerParts parts);

  /// One frame: the detections captured at `stamp`. Throws kestrel::Error, and changes nothing,
  /// if `stamp` is earlier than the previous frame's.
  msg::Tracks step(Time stamp, const std::vector<Eigen::Vector3d>& detections);

  /// Live tracks, tentative ones included.
  std::size_t size() const { return tracks_.size(); }
  const TrackerCounts& counts() const { return counts_; }

 private:
  struct Track {
    TrackStatus status;
    std::unique_ptr<TrackFilter> filter;
    Eigen::Vector3d detection = Eigen::Vector3d::Zero();  ///< the last one associated
  };
  void start_track(const Eigen::Vector3d& detection);

  TrackerParts parts_;
  std::vector<Track> tracks_;  // in order of birth
  std::uint64_t next_id_ = 1;
  std::optional<Time> last_stamp_;
  TrackerCounts counts_;
};

}  // namespace kestrel::tracking
