#include "device_clock.hpp"

#include <algorithm>

namespace kestrel::ocams {

void DeviceClock::reset() {
  offsets_.clear();
  unwrapped_base_ = 0;
  last_device_ms_.reset();
}

Time DeviceClock::map(std::uint32_t device_ms, Time arrival) {
  if (last_device_ms_) {
    const std::uint32_t step = device_ms - *last_device_ms_;  // modulo 2^32
    if (step > 0x80000000u) {                                 // backwards: not a wrap but a restart
      reset();
      ++restarts_;
    } else if (device_ms < *last_device_ms_) {
      unwrapped_base_ += std::int64_t{1} << 32;
    }
  }
  last_device_ms_ = device_ms;
  const std::int64_t device_ns = (unwrapped_base_ + device_ms) * 1'000'000;
  offsets_.push_back(arrival.count() - device_ns);
  if (offsets_.size() > window_) offsets_.pop_front();
  const std::int64_t offset = *std::min_element(offsets_.begin(), offsets_.end());
  Time stamp(device_ns + offset);
  stamp = std::min(stamp, arrival);
  stamp = std::max(stamp, last_stamp_);
  last_stamp_ = stamp;
  return stamp;
}

}  // namespace kestrel::ocams
