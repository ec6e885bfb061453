// The `particle` filter component, and the deprecated `particle_tracker` node type of release
// 0.1, kept for one release: it takes the old flat parameters and builds the tracker that
// `type: tracker` with `filter: particle` builds, random streams included (see CHANGELOG.md).
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/deprecated_tracker.hpp>

#include "particle_filter.hpp"

namespace kestrel::tracking {

struct OldParticleTracker {
  static constexpr const char* kType = "particle_tracker";
  static constexpr const char* kFilter = "particle";
  using FilterComponent = ParticleFilter;
  using FilterConfig = ParticleOptions;
  // The seed `tracker` gives its `filter` component: the same tracks as the new form.
  static std::shared_ptr<Filter> make_filter(const NodeInit& init, const ParticleOptions& cfg) {
    return std::make_shared<ParticleFilter>(cfg, detail::derive_seed(init.seed(), "filter"));
  }
};
using ParticleTracker = DeprecatedTracker<OldParticleTracker>;
KESTREL_REGISTER_NODE(ParticleTracker)

}  // namespace kestrel::tracking

KESTREL_REGISTER_COMPONENT(kestrel::tracking::Filter, kestrel::tracking::ParticleFilter)
