#pragma once
// The deprecated node types `kalman_tracker` and `particle_tracker`: their old flat parameters
// (the filter's, max_misses, confirm_hits, selection, associator), bound to the configs of the
// tracker's components, build the TrackerParts the `tracker` node would build. They are kept for
// one release (see CHANGELOG.md); delete this file with them.
#include <memory>
#include <string>
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

/// Logs, once per process and node type, that `type` is deprecated and what replaces it.
void warn_deprecated(Logger& log, std::string_view type, std::string_view replacement);

/// A deprecated tracker node type. `Old` says what differs between them:
///   static constexpr const char* kType;        // "kalman_tracker"
///   static constexpr const char* kFilter;      // "kalman": the filter component it stands for
///   using FilterComponent = KalmanFilter;      // with static declare(ConfigSpec<C>&)
///   using FilterConfig = KalmanConfig;
///   static std::shared_ptr<Filter> make_filter(const NodeInit&, const FilterConfig&);
template <class Old>
class DeprecatedTracker final : public TrackerNode {
 public:
  using Config = DeprecatedTrackerConfig<typename Old::FilterConfig>;

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    Old::FilterComponent::declare(c);
    ConsecutiveMissesDeleter::declare(c);
    ConsecutiveHitsInitiator::declare(c);
    c.choice("selection", &Config::selection, selection_choices())
        .describe("which track is the target (paper: the longest-living)");
    declare_associator(c, &Config::associator);
    const std::string filter = Old::kFilter;
    return with_ports(NodeSpec(Old::kType, "Deprecated: use type tracker with filter: " + filter))
        .details("Kept for one release (see CHANGELOG.md). The same tracker as `type: tracker` with `filter: {type: " +
                 filter +
                 ", ...}` (this node's filter parameters), `initiator: {type: consecutive_hits, confirm_hits}`, "
                 "`deleter: {type: consecutive_misses, max_misses}`, `selector: <selection>` and the same "
                 "`associator`.")
        .config(std::move(c));
  }

  explicit DeprecatedTracker(NodeInit& init) : DeprecatedTracker(init, init.config<Config>()) {}

 private:
  DeprecatedTracker(NodeInit& init, const Config& cfg)
      : TrackerNode(
            TrackerParts{Old::make_filter(init, static_cast<const typename Old::FilterConfig&>(cfg)),
                         init.make_component<Associator>("associator"),
                         std::make_shared<ConsecutiveHitsInitiator>(static_cast<const ConsecutiveHitsConfig&>(cfg)),
                         std::make_shared<ConsecutiveMissesDeleter>(static_cast<const ConsecutiveMissesConfig&>(cfg)),
                         make_selector(cfg.selection)}) {
    warn_deprecated(init.log(), Old::kType,
                    std::string("type: tracker with filter: {type: ") + Old::kFilter + ", ...}");
  }
};

}  // namespace kestrel::tracking
