#pragma once
// CLOCK_MONOTONIC time and absolute sleeps (clock_nanosleep with TIMER_ABSTIME: no drift).

#include <cstdint>

#include "core/status.hpp"
#include "hal_concepts.hpp"

namespace tread::hal {

class PosixClock {
 public:
  [[nodiscard]] std::int64_t now_ns() const noexcept;
  /// Sleeps until the absolute CLOCK_MONOTONIC deadline; retries on EINTR.
  /// @retval Status::io_error  clock_nanosleep failed otherwise
  Status sleep_until_ns(std::int64_t deadline_ns) noexcept;
};

static_assert(Clock<PosixClock>);

}  // namespace tread::hal
