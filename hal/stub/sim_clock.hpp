#pragma once
// A simulated monotonic clock: time moves only when someone sleeps or advances it.

#include <cstdint>

#include "core/status.hpp"
#include "hal_concepts.hpp"

namespace tread::hal {

class SimClock {
 public:
  explicit SimClock(std::int64_t start_ns = 0) noexcept : now_ns_(start_ns) {}

  [[nodiscard]] std::int64_t now_ns() const noexcept { return now_ns_; }

  /// Jumps to the deadline (never backwards), plus the configured wake-up latency.
  Status sleep_until_ns(std::int64_t deadline_ns) noexcept {
    if (deadline_ns > now_ns_) {
      now_ns_ = deadline_ns;
    }
    now_ns_ += wake_latency_ns_;
    return Status::ok;
  }

  void advance_ns(std::int64_t delta_ns) noexcept { now_ns_ += delta_ns > 0 ? delta_ns : 0; }
  void set_wake_latency_ns(std::int64_t latency_ns) noexcept { wake_latency_ns_ = latency_ns; }

 private:
  std::int64_t now_ns_;
  std::int64_t wake_latency_ns_{0};
};

static_assert(Clock<SimClock>);

}  // namespace tread::hal
