#include "kestrel/tracking/tracker_params.hpp"

#include "kestrel/messages/detections.hpp"

namespace kestrel::tracking {

NodeSpec& add_track_management_params(NodeSpec& spec) {
  return spec
      .param(param("max_misses", 10).range(0, 100000).describe("consecutive missed frames before a track is deleted"))
      .param(param("confirm_hits", 1)
                 .range(1, 100000)
                 .describe("hits before a track is published; 1 = at birth (the paper); a tentative track is deleted "
                           "at its first miss"))
      .param(param("selection", std::string("longest_living"))
                 .one_of({"longest_living", "most_hits", "nearest"})
                 .describe("which track is the target (paper: the longest-living)"))
      .param(component_param("associator", "associator", "hungarian")
                 .describe("data association: hungarian or greedy, with its metric and gate"));
}

TrackManager make_track_manager(NodeInit& init, FilterFactory factory) {
  return TrackManager(
      init.make_component<Associator>("associator"), std::move(factory),
      TrackManagerOptions{init.param<int>("max_misses"), parse_selection(init.param<std::string>("selection")),
                          init.param<int>("confirm_hits")});
}

msg::Tracks track(TrackManager& manager, const msg::Detections& detections) {
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(detections.items.size());
  for (const auto& d : detections.items) positions.push_back(d.position);
  msg::Tracks tracks = manager.step(detections.stamp, positions);
  tracks.frame = detections.frame;
  return tracks;
}

}  // namespace kestrel::tracking
