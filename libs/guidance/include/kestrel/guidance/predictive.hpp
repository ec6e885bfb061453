#pragma once
// `predictive`: predict the target over a horizon from the aim's world estimate, find the
// earliest time at which the hunter, within its limits, can be at the aim pose of the predicted
// target (kestrel/guidance/intercept.hpp), and fly there on the least-effort rendezvous
// trajectory, arriving with the target's velocity: aligned for the shot. It plans again at every
// frame, so a manoeuvre moves the intercept point. Its weakness: a prediction held seconds ahead
// is only as good as the target's steadiness; against a jinking target the point jumps.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/guidance/intercept.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct PredictiveConfig {
  enum class Model { constant_velocity, constant_acceleration };
  Model prediction = Model::constant_velocity;
  double horizon_s = 4.0;              ///< how far ahead an intercept is looked for
  double step_s = 0.05;                ///< the search grid
  double acceleration_fraction = 0.7;  ///< the share of the hunter's acceleration the plan uses
  double min_time_to_go_s = 0.3;       ///< the plan never aims sooner than this
  double handover_m = 1.5;             ///< terminal phase within this distance of the aim pose
};

class Predictive final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit Predictive(const ComponentInit& init);
  explicit Predictive(PredictiveConfig config) : cfg_(config) {}
  GuidanceCommand command(const Engagement& e) override;
  /// The plan for this engagement (none: no intercept within the horizon).
  std::optional<InterceptPlan> plan(const Engagement& e) const;

 private:
  PredictiveConfig cfg_;
};

}  // namespace kestrel::guidance
