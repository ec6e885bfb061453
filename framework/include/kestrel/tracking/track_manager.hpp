#pragma once
// Multi-target track management shared by the trackers (paper, section 2.3): predict every
// track, associate detections, update the matched tracks, give birth to a track for each
// detection no track claimed, delete a track after too many consecutive misses, and select the
// target to aim at. The filter inside a track (Kalman, particles) is supplied by the tracker.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/messages/tracks.hpp"
#include "kestrel/time.hpp"
#include "kestrel/tracking/associator.hpp"

namespace kestrel::tracking {

/// One track's estimator.
class TrackFilter {
 public:
  virtual ~TrackFilter() = default;
  virtual void predict(double dt) = 0;
  virtual void update(const Eigen::Vector3d& z) = 0;
  virtual PredictedMeasurement predicted_measurement() const = 0;
  virtual Eigen::VectorXd state() const = 0;
  virtual Eigen::MatrixXd covariance() const = 0;
};

/// Makes the filter of a new track from its first detection.
using FilterFactory = std::function<std::unique_ptr<TrackFilter>(const Eigen::Vector3d& first_detection)>;

enum class Selection {
  longest_living,  ///< the paper's rule: noise tracks are short-lived
  most_hits,
  nearest,  ///< closest to the camera
};

/// "longest_living", "most_hits" or "nearest".
Selection parse_selection(const std::string& name);

struct TrackManagerOptions {
  int max_misses = 10;  ///< consecutive frames without a detection before deletion
  Selection selection = Selection::longest_living;
  /// Hits before a track is published (and can be the target); 1 publishes every track at
  /// birth, as the paper does. More keeps one-frame noise out of the output. A tentative track
  /// (fewer hits) is deleted at its first miss.
  int confirm_hits = 1;
};

class TrackManager {
 public:
  TrackManager(std::shared_ptr<const Associator> associator, FilterFactory factory, TrackManagerOptions options);

  /// One frame: detections (camera frame) captured at `stamp`.
  msg::Tracks step(Time stamp, const std::vector<Eigen::Vector3d>& detections);

  std::size_t size() const { return tracks_.size(); }

 private:
  struct Track {
    std::uint64_t id = 0;
    int age = 0, hits = 0, misses = 0;
    bool confirmed = false;
    std::unique_ptr<TrackFilter> filter;
  };

  std::shared_ptr<const Associator> associator_;
  FilterFactory factory_;
  TrackManagerOptions options_;
  std::vector<Track> tracks_;
  std::uint64_t next_id_ = 1;
  std::optional<Time> last_stamp_;
};

}  // namespace kestrel::tracking
