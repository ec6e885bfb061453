#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace kestrel::detail {

Progress::Progress(const RunState& run, bool requested)
    : run_(run),
      enabled_(requested && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

std::uint64_t Progress::source_frames() const {
  std::uint64_t frames = 0;
  for (const auto& node : run_.nodes)
    if (node->has_timer()) frames = std::max(frames, node->calls.load(std::memory_order_relaxed));
  return frames;
}

void Progress::update(Time run_time) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(1)) return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const std::uint64_t frames = source_frames();
  std::fprintf(stderr, "\r[kestrel] t = %.1f s | %llu frames | %.1f frames/s | %.2fx real time   ",
               to_seconds(run_time), static_cast<unsigned long long>(frames),
               static_cast<double>(frames) / std::max(wall, 1e-9), to_seconds(run_time) / std::max(wall, 1e-9));
  std::fflush(stderr);
  printed_ = true;
}

void Progress::finish() {
  if (printed_) std::fputc('\n', stderr);
  printed_ = false;
}

}  // namespace kestrel::detail
