// Deprecated: the `kalman_tracker` node type of release 0.1, kept for one release. It takes the
// old flat parameters and builds the tracker that `type: tracker` with `filter: kalman` builds
// (see CHANGELOG.md):
//
//   type: kalman_tracker                 type: tracker
//   params: {r: 1.0, max_misses: 10,     params: {filter: {type: kalman, r: 1.0},
//            confirm_hits: 2,                     deleter: {type: consecutive_misses, max_misses: 10},
//            selection: nearest}                  initiator: {type: consecutive_hits, confirm_hits: 2},
//                                                 selector: nearest}
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/deprecated_tracker.hpp>
#include <kestrel/tracking/kalman_filter.hpp>

namespace kestrel::tracking {

using KalmanTrackerConfig = DeprecatedTrackerConfig<KalmanConfig>;

class KalmanTracker final : public TrackerNode {
 public:
  static NodeSpec spec() {
    ConfigSpec<KalmanTrackerConfig> c;
    KalmanFilter::declare(c);
    declare_deprecated_track_management(c);
    return with_ports(NodeSpec("kalman_tracker", "Deprecated: use type tracker with filter: kalman"))
        .details(
            "Kept for one release. The same tracker as `type: tracker` with `filter: {type: kalman, q, r, p}`, "
            "`initiator: {type: consecutive_hits, confirm_hits}`, `deleter: {type: consecutive_misses, "
            "max_misses}` and `selector: <selection>`.")
        .config(std::move(c));
  }

  explicit KalmanTracker(NodeInit& init) : KalmanTracker(init, init.config<KalmanTrackerConfig>()) {}

 private:
  KalmanTracker(NodeInit& init, const KalmanTrackerConfig& cfg)
      : TrackerNode(deprecated_tracker_parts(init, cfg,
                                             std::make_shared<KalmanFilter>(static_cast<const KalmanConfig&>(cfg)))) {
    warn_deprecated(init.log(), "kalman_tracker", "type: tracker with filter: {type: kalman, ...}");
  }
};
KESTREL_REGISTER_NODE(KalmanTracker)

}  // namespace kestrel::tracking
