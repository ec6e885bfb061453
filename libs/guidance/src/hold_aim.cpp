#include "kestrel/guidance/hold_aim.hpp"

namespace kestrel::guidance {

ComponentSpec HoldAim::spec() {
  return ComponentSpec("hold_aim", "The paper's aim law: fly to the aim pose from the start (section 2.4)")
      .details(
          "The whole engagement is the terminal phase: the reference is pulled to the aim pose (where the target "
          "sits at x_E^d) with the target's velocity fed forward, at the aim planner's gain_1_s. A tail chase of a "
          "fast target.");
}

}  // namespace kestrel::guidance
