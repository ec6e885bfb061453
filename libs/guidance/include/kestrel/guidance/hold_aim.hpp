#pragma once
// `hold_aim`: the paper's law (section 2.4). It is the terminal phase from the start: the hunter
// flies to the aim pose, where the target sits at x_E^d, with the target's velocity fed
// forward. It follows rather than anticipates: a tail chase of a fast target.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

class HoldAim final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit HoldAim(const ComponentInit&) {}
  HoldAim() = default;
  GuidanceCommand command(const Engagement&) override { return terminal_phase(); }
};

}  // namespace kestrel::guidance
