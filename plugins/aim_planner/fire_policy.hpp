#pragma once
// The fire policy, a component of kind "fire_policy": whether a shot the aim could make now is
// worth a net.
//
//   threshold       the aim's own thresholds (fire_probability, capture_radius_m and their last-net
//                   values), as the paper graphs fire
//   capture_value   the chance of a capture now, counted on the target's sampled futures, against
//                   what keeping the net is worth: the planner's best later launch on the same
//                   futures, its chance discounted for the wait
#include <optional>
#include <string_view>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::aim {

/// What the fire policy weighs, each frame the target is seen.
struct FireChances {
  bool within_thresholds = false;  ///< the aim's own thresholds pass
  double now = 0.0;                ///< the chance a net launched now holds the target (the futures)
  /// What keeping the net is worth: the planner's best later launch, its chance discounted for the
  /// wait (none: no planner that plans on the futures, or nothing within its reach).
  std::optional<double> later;
  int nets_left = -1;  ///< -1: unknown (no launcher connected)
};

class FirePolicy {
 public:
  static constexpr std::string_view kKind = "fire_policy";
  virtual ~FirePolicy() = default;
  virtual bool worth_a_net(const FireChances& chances) const = 0;
  /// Whether the policy reads the chance now on the target's futures (the aim draws them only then).
  virtual bool needs_futures() const { return false; }
};

class ThresholdFire final : public FirePolicy {
 public:
  static ComponentSpec spec();
  explicit ThresholdFire(const ComponentInit&) {}
  ThresholdFire() = default;
  bool worth_a_net(const FireChances& chances) const override { return chances.within_thresholds; }
};

struct CaptureValueConfig {
  double min_probability = 0.3;           ///< never a shot less likely than this
  double last_net_min_probability = 0.5;  ///< nor a last net's
};

class CaptureValue final : public FirePolicy {
 public:
  static ComponentSpec spec();
  explicit CaptureValue(const ComponentInit& init);
  explicit CaptureValue(CaptureValueConfig config) : cfg_(config) {}
  bool worth_a_net(const FireChances& chances) const override;
  bool needs_futures() const override { return true; }

 private:
  CaptureValueConfig cfg_;
};

}  // namespace kestrel::aim
