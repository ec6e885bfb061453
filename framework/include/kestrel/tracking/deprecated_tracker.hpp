#pragma once
// What the deprecated node types `kalman_tracker` and `particle_tracker` share: their flat track
// management parameters (max_misses, confirm_hits, selection, associator), bound to the configs
// of the tracker's components, and the same TrackerParts the `tracker` node would build. They are
// kept for one release (see CHANGELOG.md); delete this file with them.
#include <memory>
#include <string_view>

#include "kestrel/config_spec.hpp"
#include "kestrel/logger.hpp"
#include "kestrel/node.hpp"
#include "kestrel/tracking/deleter.hpp"
#include "kestrel/tracking/initiator.hpp"
#include "kestrel/tracking/selector.hpp"
#include "kestrel/tracking/track_manager.hpp"
#include "kestrel/tracking/tracker_node.hpp"

namespace kestrel::tracking {

/// The config of a deprecated tracker type: its filter's config and these, flat.
template <class FilterConfig>
struct DeprecatedTrackerConfig : FilterConfig, ConsecutiveMissesConfig, ConsecutiveHitsConfig {
  Selection selection = Selection::longest_living;
  ComponentConfig associator;
};

/// Declares max_misses, confirm_hits, selection and associator.
template <class Config>
void declare_deprecated_track_management(ConfigSpec<Config>& c) {
  ConsecutiveMissesDeleter::declare(c);
  ConsecutiveHitsInitiator::declare(c);
  c.choice("selection", &Config::selection, selection_choices())
      .describe("which track is the target (paper: the longest-living)");
  declare_associator(c, &Config::associator);
}

/// Logs, once per process and node type, that `type` is deprecated and what replaces it.
void warn_deprecated(Logger& log, std::string_view type, std::string_view replacement);

/// The parts a `tracker` with these settings would have, around `filter`.
template <class Config>
TrackerParts deprecated_tracker_parts(const NodeInit& init, const Config& cfg, std::shared_ptr<Filter> filter) {
  return TrackerParts{std::move(filter), init.make_component<Associator>("associator"),
                      std::make_shared<ConsecutiveHitsInitiator>(static_cast<const ConsecutiveHitsConfig&>(cfg)),
                      std::make_shared<ConsecutiveMissesDeleter>(static_cast<const ConsecutiveMissesConfig&>(cfg)),
                      make_selector(cfg.selection)};
}

}  // namespace kestrel::tracking
