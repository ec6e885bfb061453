#pragma once
// The status line of a long run on a terminal: run time, source frames and rates. Written to
// stderr at most once a second, and only when asked for and stderr is a terminal.
#include <chrono>

#include "run_state.hpp"

namespace kestrel::detail {

class Progress {
 public:
  Progress(const RunState& run, bool requested);
  void update(Time run_time);
  /// Ends the status line so that later output starts on a fresh line.
  void finish();

 private:
  std::uint64_t source_frames() const;

  const RunState& run_;
  bool enabled_;
  bool printed_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace kestrel::detail
