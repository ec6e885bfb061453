#include "kestrel/tracking/tracker_node.hpp"

#include <fmt/format.h>

namespace kestrel::tracking {

NodeSpec TrackerNode::with_ports(NodeSpec spec) {
  spec.input(kDetections, "detections of one frame (camera frame)")
      .output(kTracks, "every confirmed track with its state and covariance, and the selected target");
  return spec;
}

void TrackerNode::process(Context& ctx) {
  const auto detections = ctx.get(kDetections);
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(detections->items.size());
  for (const auto& d : detections->items) positions.push_back(d.position);
  msg::Tracks tracks = manager_.step(detections->stamp, positions);
  tracks.frame = detections->frame;
  ctx.publish(kTracks, std::move(tracks));
}

void TrackerNode::finish(Context& ctx) {
  const TrackerCounts& c = manager_.counts();
  ReportSection section;
  section.quantity("frames", c.frames)
      .metric("empty_frames", c.empty_frames, "frames", Better::lower)
      .metric("tracks_started", c.tracks_started, "", Better::lower)
      .metric("tracks_confirmed", c.tracks_confirmed, "", Better::lower)
      .metric("target_coasted_frames", c.target_coasted_frames, "frames", Better::lower);
  section.markdown(fmt::format(
      "| frames | without detections | tracks started | confirmed | target coasting |\n|---:|---:|---:|---:|---:|\n"
      "| {} | {} | {} | {} | {} |\n",
      c.frames, c.empty_frames, c.tracks_started, c.tracks_confirmed, c.target_coasted_frames));
  ctx.set_report_section(ctx.id(), section);
}

}  // namespace kestrel::tracking
