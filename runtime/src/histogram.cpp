#include "kestrel/runtime/histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace kestrel {

// Values below 2^kSubBits go in their own bucket; above that, each power of two is split into
// 2^kSubBits equal parts.
int DurationHistogram::bucket_of(std::uint64_t v) {
  if (v < (1u << kSubBits)) return static_cast<int>(v);
  const int msb = 63 - std::countl_zero(v);
  const int shift = msb - kSubBits;
  const auto sub = static_cast<int>((v >> shift) & ((1u << kSubBits) - 1));
  return ((shift + 1) << kSubBits) + sub;
}

std::uint64_t DurationHistogram::upper_edge(int bucket) {
  const int group = bucket >> kSubBits;
  const std::uint64_t sub = static_cast<std::uint64_t>(bucket & ((1 << kSubBits) - 1));
  if (group == 0) return sub;
  const int shift = group - 1;
  return (((1ull << kSubBits) | sub) << shift) + ((1ull << shift) - 1);
}

void DurationHistogram::record(std::int64_t ns) {
  const std::uint64_t v = ns < 0 ? 0 : static_cast<std::uint64_t>(ns);
  ++buckets_[static_cast<std::size_t>(bucket_of(v))];
  ++count_;
  sum_ += static_cast<std::int64_t>(v);
  max_ = std::max(max_, static_cast<std::int64_t>(v));
}

std::int64_t DurationHistogram::quantile(double q) const {
  if (count_ == 0) return 0;
  const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (int b = 0; b < kBuckets; ++b) {
    seen += buckets_[static_cast<std::size_t>(b)];
    if (seen >= std::max<std::uint64_t>(rank, 1)) return std::min(static_cast<std::int64_t>(upper_edge(b)), max_);
  }
  return max_;
}

}  // namespace kestrel
