#pragma once
// The initiator: which detections start tracks, and the life of a track until it is confirmed.
// A new track is tentative: not published, never the target. The initiator confirms it (then the
// deleter owns its end) or drops it.
#include <Eigen/Core>
#include <cstddef>
#include <string_view>
#include <vector>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/track_status.hpp"

namespace kestrel::tracking {

class Initiator {
 public:
  static constexpr std::string_view kKind = "initiator";
  virtual ~Initiator() = default;

  /// The detections that start a track, as indices into `detections`, in the order the tracks
  /// are born. `unclaimed` (ascending) are those the associator gave to no track.
  virtual std::vector<std::size_t> initiate(const std::vector<Eigen::Vector3d>& detections,
                                            const std::vector<std::size_t>& unclaimed) const = 0;
  /// Whether a tentative track is confirmed now (asked at birth and after every frame).
  virtual bool confirms(const TrackStatus& tentative) const = 0;
  /// Whether a tentative track is deleted now (asked after every frame).
  virtual bool drops(const TrackStatus& tentative) const = 0;
};

struct ConsecutiveHitsConfig {
  int confirm_hits = 1;
};

/// The paper's rule, with confirmation: every detection no track claims starts a track; a track
/// is confirmed at its `confirm_hits`-th hit (1: at birth, as the paper publishes every track); a
/// tentative track is dropped at its first miss, so its hits are consecutive.
class ConsecutiveHitsInitiator final : public Initiator {
 public:
  static ComponentSpec spec();
  /// Declares confirm_hits.
  static void declare(ConfigSpec<ConsecutiveHitsConfig>& c) {
    c.param("confirm_hits", &ConsecutiveHitsConfig::confirm_hits)
        .range(1, 100000)
        .describe(
            "hits before a track is published and can be the target; 1 = at birth (the paper); a tentative track is "
            "deleted at its first miss");
  }

  explicit ConsecutiveHitsInitiator(const ComponentInit& init);
  explicit ConsecutiveHitsInitiator(ConsecutiveHitsConfig config) : cfg_(config) {}

  std::vector<std::size_t> initiate(const std::vector<Eigen::Vector3d>& detections,
                                    const std::vector<std::size_t>& unclaimed) const override;
  bool confirms(const TrackStatus& tentative) const override;
  bool drops(const TrackStatus& tentative) const override;

 private:
  ConsecutiveHitsConfig cfg_;
};

}  // namespace kestrel::tracking
