#pragma once
// Time in kestrel: one integer clock shared by every executor.
//
// A run's clock starts at zero. Under the lockstep executor it is simulated time; under the
// realtime executor it is steady wall-clock time since the run started. Integer nanoseconds keep
// lockstep runs bit-identical (no floating-point drift in the schedule).
#include <chrono>
#include <cmath>
#include <cstdint>

namespace kestrel {

using Duration = std::chrono::nanoseconds;
/// Time since the start of the run.
using Time = std::chrono::nanoseconds;

inline double to_seconds(Duration d) { return std::chrono::duration<double>(d).count(); }

inline Duration from_seconds(double seconds) {
  return Duration(static_cast<std::int64_t>(std::llround(seconds * 1e9)));
}

}  // namespace kestrel
