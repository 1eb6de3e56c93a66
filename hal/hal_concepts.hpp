#pragma once
// What the real-time loop needs from its edges, as C++20 concepts (checked at compile time, no
// virtual dispatch on the hot path). Backends: socketcan/, gpiod/, posix/, stub/; for bare-metal
// Cortex-M targets semihost/ (files, console, exit status) and cortex_m/ (SysTick tick counter).

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/status.hpp"
#include "proto/can_frame.hpp"

namespace tread::hal {

/// A CAN endpoint: non-blocking send and receive.
template <typename B>
concept CanBus = requires(B bus, const proto::CanFrame& out, proto::CanFrame& in) {
  { bus.send(out) } -> std::same_as<Status>;    // Status::would_block when the queue is full
  { bus.receive(in) } -> std::same_as<Status>;  // Status::would_block when nothing is queued
};

/// A CanBus that can also block until a frame is queued or an absolute CLOCK_MONOTONIC deadline
/// passes (Status::ok: a frame is queued; Status::would_block: the deadline passed). An
/// event-driven loop (sync mode) sleeps on it instead of polling.
template <typename B>
concept WaitableCanBus = CanBus<B> && requires(B bus, std::int64_t deadline_ns) {
  { bus.wait_until_ns(deadline_ns) } -> std::same_as<Status>;
};

/// A CanBus that can also queue several frames in one call, in order: one wake-up of a receiver
/// waiting on the other end (or one system call) for the lot instead of one per frame. Returns how
/// many it queued, the first ones of `frames`; the rest were refused (queue full) and counted as
/// dropped, as send() counts a refused frame. A loop sends its cycle's frames this way where the
/// bus offers it.
template <typename B>
concept BatchCanBus = CanBus<B> && requires(B bus, std::span<const proto::CanFrame> frames) {
  { bus.send_batch(frames) } -> std::same_as<std::size_t>;
};

/// A CanBus that can also take several queued frames in one call, in order (one system call for
/// the lot instead of one per frame and one more to find the queue empty). Returns how many it
/// wrote to the front of `frames`: fewer than `frames.size()` when no more were queued, 0 when none
/// was. A loop drains its bus this way where the bus offers it.
template <typename B>
concept BatchReceiveCanBus = CanBus<B> && requires(B bus, std::span<proto::CanFrame> frames) {
  { bus.receive_batch(frames) } -> std::same_as<std::size_t>;
};

/// Monotonic time in nanoseconds and absolute sleeps.
template <typename C>
concept Clock = requires(C clock, std::int64_t deadline_ns) {
  { clock.now_ns() } -> std::same_as<std::int64_t>;
  { clock.sleep_until_ns(deadline_ns) } -> std::same_as<Status>;
};

/// A digital output (cycle or fault pin).
template <typename P>
concept OutputPin = requires(P pin, bool level) {
  { pin.set(level) } -> std::same_as<Status>;
};

/// A pin that does nothing: the loop runs without a cycle pin.
struct NoPin {
  Status set(bool /*level*/) noexcept { return Status::ok; }
};
static_assert(OutputPin<NoPin>);

}  // namespace tread::hal
