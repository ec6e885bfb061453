#pragma once
// A fixed-size log-linear histogram of durations (nanoseconds). Memory stays constant however
// long the run is, which keeps RSS flat, and quantiles are within about 1.6 % of the true value.
#include <array>
#include <cstdint>

namespace kestrel {

class DurationHistogram {
 public:
  void record(std::int64_t ns);
  std::uint64_t count() const { return count_; }
  std::int64_t max() const { return max_; }
  double mean() const { return count_ ? static_cast<double>(sum_) / static_cast<double>(count_) : 0.0; }
  /// The q-quantile (0..1), as the upper edge of the bucket that holds it.
  std::int64_t quantile(double q) const;

 private:
  static constexpr int kSubBits = 6;  // 64 linear sub-buckets per power of two
  static constexpr int kBuckets = (64 - kSubBits + 1) << kSubBits;
  static int bucket_of(std::uint64_t v);
  static std::uint64_t upper_edge(int bucket);

  std::array<std::uint64_t, kBuckets> buckets_{};
  std::uint64_t count_ = 0;
  std::int64_t max_ = 0;
  std::int64_t sum_ = 0;
};

}  // namespace kestrel
