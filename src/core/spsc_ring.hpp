#pragma once
// A single-producer single-consumer ring of fixed capacity: lock-free, wait-free, no heap. One
// thread pushes, one other thread pops; neither ever blocks the other (a full ring refuses the
// push, an empty one the pop). For handing frames and log records between a real-time thread and
// the rest of a process.
//
// The write index is a 32-bit atomic that only ever grows (modulo 2^32): a waiter can sleep on it
// (a futex on Linux, hal/posix/thread_can_link.hpp) until the producer moves it.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace tread::core {

template <typename T, std::size_t Capacity>
class SpscRing {
  static_assert(Capacity >= 2 && (Capacity & (Capacity - 1)) == 0,
                "capacity: a power of two (indices wrap with a mask)");
  static_assert(Capacity <= (std::size_t{1} << 31), "capacity: indices are 32-bit");
  static_assert(std::is_trivially_copyable_v<T>, "elements are copied in and out");
  static_assert(std::atomic<std::uint32_t>::is_always_lock_free);

 public:
  static constexpr std::size_t kCapacity = Capacity;

  /// Producer side. False when the ring is full (the element is not stored).
  bool push(const T& value) noexcept {
    const std::uint32_t head = head_.load(std::memory_order_relaxed);
    const std::uint32_t tail = tail_.load(std::memory_order_acquire);
    if (head - tail >= Capacity) {
      return false;
    }
    slots_[head & kMask] = value;
    head_.store(head + 1U, std::memory_order_release);
    return true;
  }

  /// Consumer side. False when the ring is empty.
  bool pop(T& value) noexcept {
    const std::uint32_t tail = tail_.load(std::memory_order_relaxed);
    const std::uint32_t head = head_.load(std::memory_order_acquire);
    if (head == tail) {
      return false;
    }
    value = slots_[tail & kMask];
    tail_.store(tail + 1U, std::memory_order_release);
    return true;
  }

  /// Elements queued (exact on the consumer's side, a snapshot elsewhere).
  [[nodiscard]] std::size_t size() const noexcept {
    return static_cast<std::size_t>(head_.load(std::memory_order_acquire) -
                                    tail_.load(std::memory_order_acquire));
  }
  [[nodiscard]] bool empty() const noexcept { return size() == 0U; }

  /// The write index, for a waiter: it changes with every push.
  [[nodiscard]] std::atomic<std::uint32_t>& write_index() noexcept { return head_; }

 private:
  static constexpr std::uint32_t kMask = static_cast<std::uint32_t>(Capacity - 1U);

  // Producer and consumer indices on their own cache lines: no false sharing between the threads.
  alignas(64) std::atomic<std::uint32_t> head_{0};
  alignas(64) std::atomic<std::uint32_t> tail_{0};
  alignas(64) std::array<T, Capacity> slots_{};
};

}  // namespace tread::core
