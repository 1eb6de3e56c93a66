#include "posix/thread_can_link.hpp"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <ctime>

#include "posix/posix_clock.hpp"

namespace tread::hal {
namespace {

// The link's time: CLOCK_MONOTONIC, as the node's clock reads it.
std::int64_t monotonic_ns() noexcept {
  return PosixClock{}.now_ns();
}

// FUTEX_WAIT_BITSET takes an absolute CLOCK_MONOTONIC timeout (FUTEX_WAIT's is relative).
void futex_wait(std::atomic<std::uint32_t>& word, std::uint32_t expected,
                std::int64_t deadline_ns) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the futex word is the atomic's
  static_cast<void>(::syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word),
                              FUTEX_WAIT_BITSET | FUTEX_PRIVATE_FLAG, expected, &ts, nullptr,
                              FUTEX_BITSET_MATCH_ANY));
}

void futex_wake(std::atomic<std::uint32_t>& word) noexcept {
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast)
  static_cast<void>(::syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word),
                              FUTEX_WAKE | FUTEX_PRIVATE_FLAG, 1, nullptr, nullptr, 0));
}

}  // namespace

Status ThreadCanEndpoint::send(const proto::CanFrame& frame) noexcept {
  return send_batch(std::span<const proto::CanFrame>(&frame, 1)) == 1U ? Status::ok
                                                                       : Status::would_block;
}

std::size_t ThreadCanEndpoint::send_batch(std::span<const proto::CanFrame> frames) noexcept {
  std::size_t queued = 0;
  for (const proto::CanFrame& frame : frames) {
    proto::CanFrame stamped = frame;
    stamped.timestamp_ns = monotonic_ns();
    if (!out_.ring.push(stamped)) {
      break;  // full: the rest are refused too, so that what arrives keeps its order
    }
    ++queued;
  }
  tx_dropped_ += frames.size() - queued;
  if (queued == 0U) {
    return 0U;
  }
  // Paired with the waiter's fence: either it sees the new write index before sleeping, or this
  // sees its flag and wakes it. The flag is taken, so frames queued before the waiter sleeps again
  // cost one wake-up call.
  std::atomic_thread_fence(std::memory_order_seq_cst);
  if (out_.waiting.load(std::memory_order_relaxed) != 0U &&
      out_.waiting.exchange(0U, std::memory_order_relaxed) != 0U) {
    ++wake_calls_;
    futex_wake(out_.ring.write_index());
  }
  return queued;
}

Status ThreadCanEndpoint::receive(proto::CanFrame& frame) noexcept {
  return in_.ring.pop(frame) ? Status::ok : Status::would_block;
}

Status ThreadCanEndpoint::wait_until_ns(std::int64_t deadline_ns) noexcept {
  if (poll_interval_ns_ > 0) {
    for (;;) {
      if (!in_.ring.empty()) {
        return Status::ok;
      }
      const std::int64_t now = monotonic_ns();
      if (now >= deadline_ns) {
        return Status::would_block;
      }
      static_cast<void>(
          PosixClock{}.sleep_until_ns(std::min(now + poll_interval_ns_, deadline_ns)));
    }
  }
  std::atomic<std::uint32_t>& word = in_.ring.write_index();
  for (;;) {
    if (!in_.ring.empty()) {
      return Status::ok;
    }
    if (monotonic_ns() >= deadline_ns) {
      return Status::would_block;
    }
    const std::uint32_t seen = word.load(std::memory_order_acquire);
    in_.waiting.store(1U, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_seq_cst);
    if (in_.ring.empty()) {
      // Sleeps only while the write index is still `seen`: a push in between returns at once.
      futex_wait(word, seen, deadline_ns);
    }
    in_.waiting.store(0U, std::memory_order_relaxed);
  }
}

}  // namespace tread::hal
