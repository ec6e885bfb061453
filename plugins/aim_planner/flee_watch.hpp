#pragma once
// Whether the target flees the hunter. An intruder that sees its hunter runs from it: while the
// hunter closes in, its velocity points away along the line of sight, at speed. A
// target on its own path (a figure-8, a line, a random flight) moves across the line of sight as
// often as along it, and one that flies away on its own does so whether or not the hunter comes
// after it. Seen fleeing for a while, the target is an evader until reset (the aim resets it once
// nothing has been seen for flee_forget_s, not when its estimate restarts): the aim then holds it
// farther away (outside the radius where it breaks across the line of sight), follows its every
// sighting, and, once it is lost, turns to look for it where it fled. An evader calms once the
// hunter is far; a target that keeps its speed with the hunter far (calm_speed_m_s) flies its own
// path, fast, and is no evader for the rest of the engagement, whatever it did before.
#include <Eigen/Core>

namespace kestrel::aim {

struct FleeWatchConfig {
  double min_speed_m_s = 1.5;    ///< the least speed away from the hunter that is fleeing
  double min_share = 0.7;        ///< ... and the least share of the target's speed it is
  double max_range_m = 8.0;      ///< farther from the hunter, a target moving away is not fleeing it
  double min_closing_m_s = 1.0;  ///< the hunter closes on it at least this fast: it flees the hunter
  double time_s = 0.25;          ///< how long it flees without a break before it is an evader
  double calm_speed_m_s = 0.0;   ///< an evader slower than this with the hunter beyond max_range_m; 0: never checked
  double calm_time_s = 1.5;      ///< faster than calm_speed_m_s this long more than slower: no evader
};

class FleeWatch {
 public:
  explicit FleeWatch(const FleeWatchConfig& config) : cfg_(config) {}

  /// One frame with a sighting: the target's estimate and the hunter's state (world), dt since
  /// the last frame with one.
  void update(double dt, const Eigen::Vector3d& target, const Eigen::Vector3d& target_velocity,
              const Eigen::Vector3d& hunter, const Eigen::Vector3d& hunter_velocity);
  /// Whether the target has been seen fleeing (it stays so until reset).
  bool fleeing() const { return evader_; }
  /// How long it has fled without a break, s.
  double fleeing_for_s() const { return fleeing_for_s_; }
  /// Whether it was seen keeping its speed with the hunter far: no evader until reset.
  bool own_path() const { return own_path_; }
  void reset();

 private:
  FleeWatchConfig cfg_;
  double fleeing_for_s_ = 0.0;
  double restless_s_ = 0.0;  // time faster than calm_speed_m_s, less the time slower, with the hunter far
  bool evader_ = false, own_path_ = false;
};

}  // namespace kestrel::aim
