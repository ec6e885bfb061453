#include "kestrel/tracking/deleter.hpp"

namespace kestrel::tracking {

ComponentSpec ConsecutiveMissesDeleter::spec() {
  ConfigSpec<ConsecutiveMissesConfig> c;
  declare(c);
  return ComponentSpec("consecutive_misses", "Deletes a track after more than max_misses consecutive misses")
      .details(
          "A confirmed track coasts on its prediction through up to max_misses consecutive frames without a "
          "detection (an occlusion) and is deleted at the next miss (paper, section 2.3).")
      .config(std::move(c));
}

ConsecutiveMissesDeleter::ConsecutiveMissesDeleter(const ComponentInit& init)
    : cfg_(init.config<ConsecutiveMissesConfig>()) {}

bool ConsecutiveMissesDeleter::deletes(const TrackStatus& confirmed) const {
  return confirmed.misses > cfg_.max_misses;
}

}  // namespace kestrel::tracking
