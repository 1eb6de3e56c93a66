#pragma once
// Two CAN endpoints joined across threads of one process: the node's real-time thread on one end,
// the rig on the other. Each direction is a lock-free single-producer single-consumer ring (fixed
// capacity, no heap, core/spsc_ring.hpp); a sent frame is stamped with CLOCK_MONOTONIC (the
// PosixClock's time), as SocketCAN stamps a received frame. An endpoint can block until a frame
// arrives (a futex on the ring's write index, with an absolute CLOCK_MONOTONIC deadline), so an
// event-driven node sleeps until the rig's cycle frame instead of polling.
//
// Each endpoint belongs to one thread: endpoint(0) is used by one thread, endpoint(1) by another.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/spsc_ring.hpp"
#include "core/status.hpp"
#include "hal_concepts.hpp"
#include "proto/can_frame.hpp"

namespace tread::hal {

inline constexpr std::size_t kThreadLinkFrames = 512;

/// One direction: the ring and what a waiting consumer needs.
struct ThreadCanPipe {
  core::SpscRing<proto::CanFrame, kThreadLinkFrames> ring;
  std::atomic<std::uint32_t> waiting{0};  ///< the consumer sleeps (or is about to) on the ring
};

/// One end of the link. Satisfies hal::WaitableCanBus.
class ThreadCanEndpoint {
 public:
  ThreadCanEndpoint(ThreadCanPipe& in, ThreadCanPipe& out) noexcept : in_(in), out_(out) {}

  /// Stamps the frame with CLOCK_MONOTONIC and queues it for the other end.
  /// @retval Status::would_block  the other end's queue is full (frame counted as dropped)
  Status send(const proto::CanFrame& frame) noexcept;
  /// Stamps and queues `frames` in order, then wakes the other end once if it waits: a cycle's
  /// answers cost the sender one wake-up call, not one per frame (a receiver that drains each
  /// frame as it comes and sleeps again would otherwise be woken for every one, each call a
  /// cross-CPU wake-up on the sender's real-time thread). Returns how many were queued; once the
  /// queue is full the rest are refused and counted in tx_dropped().
  std::size_t send_batch(std::span<const proto::CanFrame> frames) noexcept;
  /// @retval Status::would_block  nothing queued
  Status receive(proto::CanFrame& frame) noexcept;
  /// Blocks until a frame is queued or the absolute CLOCK_MONOTONIC `deadline_ns` has passed.
  /// @retval Status::ok           a frame is queued
  /// @retval Status::would_block  the deadline passed with nothing queued
  Status wait_until_ns(std::int64_t deadline_ns) noexcept;

  /// How wait_until_ns() waits. 0 (the default): it sleeps until the other end's send wakes it (a
  /// futex wake-up, made by the sender's thread). Above 0: it looks at its queue every
  /// `interval_ns` and sleeps in between, never asking to be woken, so the other end's sends make
  /// no wake-up call; a frame is then seen up to `interval_ns` late (its timestamp is still its
  /// send time). For a rig's end whose node must not pay for waking it: waking a sleeping thread
  /// on another CPU cost the waker's thread a median 31 µs on one VM of these machines (PVM),
  /// 15–30 times the node's whole cycle. A thread's own end, set before the threads start.
  void set_poll_interval_ns(std::int64_t interval_ns) noexcept {
    poll_interval_ns_ = interval_ns > 0 ? interval_ns : 0;
  }

  [[nodiscard]] std::uint64_t tx_dropped() const noexcept { return tx_dropped_; }
  /// Wake-up calls this end made to the other (a futex wake each, only while the other waited).
  [[nodiscard]] std::uint64_t wake_calls() const noexcept { return wake_calls_; }

 private:
  ThreadCanPipe& in_;
  ThreadCanPipe& out_;
  std::uint64_t tx_dropped_{0};
  std::uint64_t wake_calls_{0};
  std::int64_t poll_interval_ns_{0};
};

/// The two pipes and their endpoints. Not movable (the endpoints refer to the pipes).
class ThreadCanLink {
 public:
  ThreadCanLink() noexcept = default;
  ThreadCanLink(const ThreadCanLink&) = delete;
  ThreadCanLink& operator=(const ThreadCanLink&) = delete;

  /// 0 or 1: what one end sends, the other receives.
  [[nodiscard]] ThreadCanEndpoint& endpoint(std::size_t index) noexcept {
    TREAD_ASSERT(index < 2U);
    return index == 0U ? a_ : b_;
  }

 private:
  ThreadCanPipe a_to_b_{};
  ThreadCanPipe b_to_a_{};
  ThreadCanEndpoint a_{b_to_a_, a_to_b_};
  ThreadCanEndpoint b_{a_to_b_, b_to_a_};
};

static_assert(WaitableCanBus<ThreadCanEndpoint> && BatchCanBus<ThreadCanEndpoint>);

}  // namespace tread::hal
