// The `particle` filter component, and the deprecated `particle_tracker` node type of release
// 0.1, kept for one release: it takes the old flat parameters and builds the tracker that
// `type: tracker` with `filter: particle` builds, random streams included (see CHANGELOG.md).
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/deprecated_tracker.hpp>

#include "particle_filter.hpp"

namespace kestrel::tracking {

using ParticleTrackerConfig = DeprecatedTrackerConfig<ParticleOptions>;

class ParticleTracker final : public TrackerNode {
 public:
  static NodeSpec spec() {
    ConfigSpec<ParticleTrackerConfig> c;
    ParticleFilter::declare(c);
    declare_deprecated_track_management(c);
    return with_ports(NodeSpec("particle_tracker", "Deprecated: use type tracker with filter: particle"))
        .details(
            "Kept for one release. The same tracker as `type: tracker` with `filter: {type: particle, ...}` (the "
            "particle filter's parameters), `initiator: {type: consecutive_hits, confirm_hits}`, `deleter: {type: "
            "consecutive_misses, max_misses}` and `selector: <selection>`, with the same random streams.")
        .config(std::move(c));
  }

  explicit ParticleTracker(NodeInit& init) : ParticleTracker(init, init.config<ParticleTrackerConfig>()) {}

 private:
  ParticleTracker(NodeInit& init, const ParticleTrackerConfig& cfg)
      : TrackerNode(deprecated_tracker_parts(
            init, cfg,
            // The seed `tracker` gives its `filter` component: the same tracks as the new form.
            std::make_shared<ParticleFilter>(static_cast<const ParticleOptions&>(cfg),
                                             detail::derive_seed(init.seed(), "filter")))) {
    warn_deprecated(init.log(), "particle_tracker", "type: tracker with filter: {type: particle, ...}");
  }
};
KESTREL_REGISTER_NODE(ParticleTracker)

}  // namespace kestrel::tracking

KESTREL_REGISTER_COMPONENT(kestrel::tracking::Filter, kestrel::tracking::ParticleFilter)
