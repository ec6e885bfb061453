#include "kestrel/tracking/initiator.hpp"

namespace kestrel::tracking {

ComponentSpec ConsecutiveHitsInitiator::spec() {
  ConfigSpec<ConsecutiveHitsConfig> c;
  declare(c);
  return ComponentSpec("consecutive_hits", "A track for each unclaimed detection, confirmed at its confirm_hits-th hit")
      .details(
          "Every detection the associator gives to no track starts a tentative track. A tentative track is not "
          "published and is never the target; it is confirmed at its confirm_hits-th hit (1: at birth, the paper's "
          "way) and deleted at its first miss, so its hits are consecutive. A lone false alarm then never shows.")
      .config(std::move(c));
}

ConsecutiveHitsInitiator::ConsecutiveHitsInitiator(const ComponentInit& init)
    : cfg_(init.config<ConsecutiveHitsConfig>()) {}

std::vector<std::size_t> ConsecutiveHitsInitiator::initiate(const std::vector<Eigen::Vector3d>&,
                                                            const std::vector<std::size_t>& unclaimed) const {
  return unclaimed;
}

bool ConsecutiveHitsInitiator::confirms(const TrackStatus& tentative) const {
  return tentative.hits >= cfg_.confirm_hits;
}

bool ConsecutiveHitsInitiator::drops(const TrackStatus& tentative) const { return tentative.misses > 0; }

}  // namespace kestrel::tracking
