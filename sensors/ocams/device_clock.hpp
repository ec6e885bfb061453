#pragma once
// Maps a device's 32-bit millisecond clock onto the runtime's clock. Every frame arrives some
// transport delay after its capture, never before, so the smallest (arrival - device time) over
// a recent window is the truest offset: a stamp is the device time plus that offset. The window
// lets the estimate follow the two clocks' drift; a wrap of the 32-bit counter (every 49.7 days)
// is unwrapped, and a jump back (the device restarted) starts the estimate afresh.
#include <cstdint>
#include <deque>
#include <kestrel/time.hpp>
#include <limits>
#include <optional>

namespace kestrel::ocams {

class DeviceClock {
 public:
  explicit DeviceClock(std::size_t window = 300) : window_(window) {}

  /// The runtime time at which a frame stamped `device_ms` by the device was captured, given
  /// when it arrived. Never later than `arrival`, and never before the previous stamp.
  Time map(std::uint32_t device_ms, Time arrival);
  /// Forgets the estimate: the device was reopened.
  void reset();
  std::uint64_t restarts() const { return restarts_; }

 private:
  std::size_t window_;
  std::deque<std::int64_t> offsets_;  // arrival - device, ns, newest last
  std::int64_t unwrapped_base_ = 0;   // ms added for the counter's wraps
  std::optional<std::uint32_t> last_device_ms_;
  Time last_stamp_{std::numeric_limits<std::int64_t>::min()};
  std::uint64_t restarts_ = 0;
};

}  // namespace kestrel::ocams
