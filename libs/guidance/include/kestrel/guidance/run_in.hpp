#pragma once
// `run_in`: a pass at speed, for a target that flees the hunter that closes on it. The hunter
// stalks it from `stalk_range_m` (horizontally), `height_m` above it, where it does not flee; once
// settled there, with the target slow, it runs in along the line of sight, speeding up at
// `acceleration_m_s2` to `speed_m_s` faster than the target, and stays level at that speed. The
// net inherits the hunter's velocity: fired from about (5 m/s + speed) times its flight time, it
// is out before the target, which reacts only when the hunter is near, has begun to move, and it
// sweeps along the line of sight, where a fleeing target goes. Within `break_off_m` the run ends
// and the stalk begins again (the second net's pass).
//
// Its weakness: it assumes the target reacts late. A target that flees from farther than the
// shot's range sees the run coming; one that is fast and never slows is never run at.
#include "kestrel/component.hpp"
#include "kestrel/guidance/guidance.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::guidance {

struct RunInConfig {
  double stalk_range_m = 14.0;        ///< horizontal distance the hunter waits at
  double height_m = 2.0;              ///< the hunter above the target, stalking and running
  double speed_m_s = 8.0;             ///< the run's speed, relative to the target
  double acceleration_m_s2 = 8.0;     ///< the run-up's: at speed early, level again at the shot
  double gain_1_s = 1.0;              ///< the pull towards the stalk point and the height
  double settle_m = 1.5;              ///< at the stalk point within this: settled
  double settle_speed_m_s = 1.5;      ///< and moving with the target within this
  double settle_s = 0.5;              ///< for this long (the hunter catches up with its reference)
  double max_target_speed_m_s = 3.0;  ///< no run at a target faster than this
  double break_off_m = 4.0;           ///< the run ends this near (horizontally)
};

class RunIn final : public Guidance {
 public:
  static ComponentSpec spec();
  explicit RunIn(const ComponentInit& init);
  explicit RunIn(RunInConfig config) : cfg_(config) {}
  GuidanceCommand command(const Engagement& e) override;
  void reset() override {
    running_ = false;
    settled_s_ = 0.0;
  }
  /// True while it runs in (false: it stalks).
  bool running() const { return running_; }

 private:
  RunInConfig cfg_;
  bool running_ = false;
  double settled_s_ = 0.0;  ///< how long it has been settled at the stalk point
};

}  // namespace kestrel::guidance
