#include "blackout_schedule.hpp"

#include <cmath>

#include "kestrel/error.hpp"

namespace kestrel::scenario {

BlackoutSchedule::BlackoutSchedule(int frames, double first_s, double period_s)
    : frames_(frames), first_(first_s), period_(period_s) {
  if (frames < 0) throw Error("a blackout cannot last a negative number of frames");
  if (!(period_s > 0.0)) throw Error("the blackout period must be positive");
}

bool BlackoutSchedule::hide(double t) {
  if (t < first_) return false;
  const auto period = static_cast<long>(std::floor((t - first_) / period_));
  if (period != current_) {
    current_ = period;
    hidden_in_current_ = 0;
  }
  if (hidden_in_current_ >= frames_) return false;
  ++hidden_in_current_;
  return true;
}

}  // namespace kestrel::scenario
