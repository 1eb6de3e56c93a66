#pragma once
// Fixed-size histogram of durations at 1 µs resolution (0 .. 20 ms, overflow bucket above), for
// percentiles without allocation in the real-time loop.

#include <array>
#include <cstdint>

namespace tread::hal {

class LatencyHistogram {
 public:
  static constexpr std::size_t kBuckets = 20'001;  ///< 0..20000 µs; the last also holds larger

  void add_ns(std::int64_t ns) noexcept {
    const std::int64_t us = ns < 0 ? 0 : ns / 1000;
    const auto bucket = static_cast<std::size_t>(
        us >= static_cast<std::int64_t>(kBuckets) ? kBuckets - 1U : static_cast<std::size_t>(us));
    ++counts_[bucket];
    ++total_;
    if (ns > max_ns_) {
      max_ns_ = ns;
    }
    sum_ns_ += ns < 0 ? 0 : ns;
  }

  /// The last bucket's value: a percentile of kOverflowUs means "kOverflowUs µs or more".
  static constexpr std::int64_t kOverflowUs = static_cast<std::int64_t>(kBuckets) - 1;

  /// The smallest bucket value (µs) at or below which fraction `q` of the samples lie
  /// (kOverflowUs: that many µs or more).
  [[nodiscard]] std::int64_t percentile_us(double q) const noexcept {
    if (total_ == 0U) {
      return 0;
    }
    const auto target = static_cast<std::uint64_t>(q * static_cast<double>(total_) + 0.5);
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kBuckets; ++i) {
      seen += counts_[i];
      if (seen >= target && seen > 0U) {
        return static_cast<std::int64_t>(i);
      }
    }
    return static_cast<std::int64_t>(kBuckets - 1U);
  }

  [[nodiscard]] std::uint64_t count() const noexcept { return total_; }
  [[nodiscard]] std::int64_t max_ns() const noexcept { return max_ns_; }
  [[nodiscard]] double mean_ns() const noexcept {
    return total_ == 0U ? 0.0 : static_cast<double>(sum_ns_) / static_cast<double>(total_);
  }
  void clear() noexcept { *this = LatencyHistogram{}; }

 private:
  std::array<std::uint32_t, kBuckets> counts_{};
  std::uint64_t total_{0};
  std::int64_t max_ns_{0};
  std::int64_t sum_ns_{0};
};

}  // namespace tread::hal
