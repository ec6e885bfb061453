#pragma once
// The tracks a tracker maintains, and which one is the selected target.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct Track {
  std::uint64_t id = 0;
  int age = 0;     ///< frames since birth
  int hits = 0;    ///< frames with an associated detection
  int misses = 0;  ///< consecutive frames without one
  /// Filter state; for the constant-acceleration model [x y z vx vy vz ax ay az].
  Eigen::VectorXd state;
  Eigen::MatrixXd covariance;
  /// The detection associated with the track at this update; NaN when it coasted (misses > 0).
  /// What was seen, unfiltered: a consumer that re-estimates the target in another frame (the
  /// aim, in the world while the camera turns) takes it rather than the filtered state.
  Eigen::Vector3d detection = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());

  Eigen::Vector3d position() const { return state.head<3>(); }
};

struct Tracks {
  Time stamp{0};
  std::string frame = "camera";
  std::vector<Track> items;
  std::optional<std::uint64_t> selected_id;  ///< the target to aim at, if any

  const Track* selected() const {
    if (!selected_id) return nullptr;
    for (const auto& t : items)
      if (t.id == *selected_id) return &t;
    return nullptr;
  }
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::Tracks, "kestrel.Tracks",
                "tracks with id, age, hits, misses, state, covariance and the selected target");
KESTREL_MESSAGE_FIELDS(kestrel::msg::Tracks,
                       {"stamp", "Time", "ns", "", "capture time of the detections of this update"},
                       {"frame", "string", "", "", "frame of the states: \"camera\""},
                       {"items", "vector<Track>", "", "", "the published (confirmed) tracks"},
                       {"items[].id", "uint64", "", "", "unique over the run, never reused"},
                       {"items[].age", "int", "frames", "", "since the track's birth"},
                       {"items[].hits", "int", "frames", "", "with an associated detection"},
                       {"items[].misses", "int", "frames", "", "consecutive ones without a detection"},
                       {"items[].state", "Eigen::VectorXd", "m, m/s, m/s^2", "in frame",
                        "filter state; constant acceleration: [x y z vx vy vz ax ay az]"},
                       {"items[].covariance", "Eigen::MatrixXd", "squares of the state's units", "in frame",
                        "state covariance, same order as state"},
                       {"items[].detection", "Eigen::Vector3d", "m", "in frame",
                        "the detection associated at this update; NaN when the track coasted"},
                       {"selected_id", "optional<uint64>", "", "", "id of the target to aim at, if any"});
