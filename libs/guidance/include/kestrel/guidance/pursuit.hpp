#pragma once
// `pursuit`: pure pursuit. The hunter flies at its top speed straight at where the aim pose is
// now, and hands over to the terminal phase within `handover_m`. It never leads: against a
// crossing target its path curves into a tail chase, and a target as fast as the hunter is never
// reached.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct PursuitConfig {
  double handover_m = 2.0;  ///< terminal phase within this distance of the aim pose
};

class Pursuit final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit Pursuit(const ComponentInit& init);
  explicit Pursuit(PursuitConfig config) : cfg_(config) {}
  GuidanceCommand command(const Engagement& e) override;

 private:
  PursuitConfig cfg_;
};

}  // namespace kestrel::guidance
