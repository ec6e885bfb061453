#pragma once
// What every tracker node type shares: the ports, one TrackManager, and the report section.
// The `tracker` node (plugins/tracker) builds its TrackerParts from components named in YAML.
#include "kestrel/config_spec.hpp"
#include "kestrel/messages/detections.hpp"
#include "kestrel/messages/tracks.hpp"
#include "kestrel/node.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/track_manager.hpp"

namespace kestrel::tracking {

class TrackerNode : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};

  /// `spec` with a tracker's ports.
  static NodeSpec with_ports(NodeSpec spec);

  explicit TrackerNode(TrackerParts parts) : manager_(std::move(parts)) {}

  /// One frame of detections in, every confirmed track and the target out, in the detections'
  /// frame.
  void process(Context& ctx) override;
  /// Reports what the tracker did (TrackerCounts) under the node's id.
  void finish(Context& ctx) override;

 protected:
  /// One frame of detections' positions, in the frame the tracks are kept in, for a node type
  /// that keeps them in another frame than the detections'.
  msg::Tracks step(Time stamp, const std::vector<Eigen::Vector3d>& positions) {
    return manager_.step(stamp, positions);
  }

 private:
  TrackManager manager_;
};

/// The `associator` component parameter, as every tracker node type declares it.
template <class Config>
ParamSpec& declare_associator(ConfigSpec<Config>& c, ComponentConfig Config::*field) {
  return c.component("associator", field, "associator", "hungarian")
      .describe("data association: hungarian or greedy, with its metric and gate (paper: hungarian, 1.0 m)");
}

}  // namespace kestrel::tracking
