#include "fire_policy.hpp"

namespace kestrel::aim {

ComponentSpec ThresholdFire::spec() {
  return ComponentSpec("threshold", "Fires on the aim's own thresholds")
      .details(
          "A shot is worth a net when the aim's thresholds pass: with fire_probability set, the chance of its shot "
          "model reaches it (last_net_probability for the last net); otherwise the predicted miss is within "
          "capture_radius_m (last_net_radius_m). The paper graphs fire this way.");
}

ComponentSpec CaptureValue::spec() {
  using C = CaptureValueConfig;
  ConfigSpec<C> c;
  c.param("min_probability", &C::min_probability)
      .range(0.0, 1.0)
      .describe("no shot whose chance of a capture is below this, whatever waiting is worth");
  c.param("last_net_min_probability", &C::last_net_min_probability)
      .range(0.0, 1.0)
      .describe("the same for the last net: a miss ends the engagement");
  return ComponentSpec("capture_value", "Fires when a capture now is worth more than keeping the net")
      .details(
          "Fires when the chance that a net launched now holds the target, counted on the target's sampled futures, "
          "is at least what keeping the net is worth: the planner's best later launch on the same futures, its chance "
          "discounted for the wait (intercept_search's hazard_time_s). A shot below min_probability "
          "(last_net_min_probability for the last net) is never worth a net. With a planner that reports no later "
          "value, the floor alone decides.")
      .config(std::move(c));
}

CaptureValue::CaptureValue(const ComponentInit& init) : cfg_(init.config<CaptureValueConfig>()) {}

bool CaptureValue::worth_a_net(const FireChances& chances) const {
  const double floor = chances.nets_left == 1 ? cfg_.last_net_min_probability : cfg_.min_probability;
  return chances.now >= floor && chances.now >= chances.later.value_or(0.0);
}

}  // namespace kestrel::aim
