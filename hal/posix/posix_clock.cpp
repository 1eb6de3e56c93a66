#include "posix/posix_clock.hpp"

#include <cerrno>
#include <ctime>

namespace tread::hal {

std::int64_t PosixClock::now_ns() const noexcept {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

Status PosixClock::sleep_until_ns(std::int64_t deadline_ns) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
  for (;;) {
    const int rc = ::clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
    if (rc == 0) {
      return Status::ok;
    }
    if (rc != EINTR) {
      return Status::io_error;
    }
  }
}

}  // namespace tread::hal
