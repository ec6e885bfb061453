#pragma once
// The deleter: when a confirmed track ends. (A tentative track's end is the initiator's call.)
#include <string_view>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/track_status.hpp"

namespace kestrel::tracking {

class Deleter {
 public:
  static constexpr std::string_view kKind = "deleter";
  virtual ~Deleter() = default;
  /// Whether a confirmed track is deleted now (asked after every frame).
  virtual bool deletes(const TrackStatus& confirmed) const = 0;
};

struct ConsecutiveMissesConfig {
  int max_misses = 10;
};

/// The paper's rule: a track coasts on its prediction through up to `max_misses` consecutive
/// frames without a detection and is deleted at the next miss.
class ConsecutiveMissesDeleter final : public Deleter {
 public:
  static ComponentSpec spec();
  /// Declares max_misses.
  static void declare(ConfigSpec<ConsecutiveMissesConfig>& c) {
    c.param("max_misses", &ConsecutiveMissesConfig::max_misses)
        .range(0, 100000)
        .describe("consecutive missed frames a track survives; it is deleted at the next");
  }

  explicit ConsecutiveMissesDeleter(const ComponentInit& init);
  explicit ConsecutiveMissesDeleter(ConsecutiveMissesConfig config) : cfg_(config) {}

  bool deletes(const TrackStatus& confirmed) const override;

 private:
  ConsecutiveMissesConfig cfg_;
};

}  // namespace kestrel::tracking
