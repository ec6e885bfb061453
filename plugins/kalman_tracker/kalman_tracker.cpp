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

struct OldKalmanTracker {
  static constexpr const char* kType = "kalman_tracker";
  static constexpr const char* kFilter = "kalman";
  using FilterComponent = KalmanFilter;
  using FilterConfig = KalmanConfig;
  static std::shared_ptr<Filter> make_filter(const NodeInit&, const KalmanConfig& cfg) {
    return std::make_shared<KalmanFilter>(cfg);
  }
};
using KalmanTracker = DeprecatedTracker<OldKalmanTracker>;
KESTREL_REGISTER_NODE(KalmanTracker)

}  // namespace kestrel::tracking
