#pragma once
// Drives a node::Node over the HAL: per cycle drain RX → node.receive → node.compute → TX → cycle
// pin.
//   periodic: own schedule on absolute deadlines (start + k·period; no drift). A cycle that
//             ends past the next deadline is an overrun: counted, the missed deadlines are
//             skipped (no burst).
//   sync:     compute when the rig's cycle frame arrives; if none arrives for the input
//             timeout, compute anyway so stale channels report zeros. On a bus that can block
//             until a frame arrives (hal::WaitableCanBus: SocketCAN, the thread link) the loop
//             sleeps until then; on others it polls every sync_poll_ns.
// The node sees the nominal cycle time (the deadline) in periodic mode and the wake time in sync
// mode: in periodic mode a recorded run is therefore replayable bit for bit.
// TX goes out in one call where the bus can queue several frames at once (hal::BatchCanBus: the
// thread link, where it costs one wake-up of a waiting rig for the cycle; SocketCAN, one sendmmsg),
// else a send() a frame. RX comes in one call where the bus can take several queued frames at once
// (hal::BatchReceiveCanBus: SocketCAN, one recvmmsg), else a receive() a frame and one more that
// finds the queue empty.
// Header-only, templated on hal concepts; no heap.

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <span>

#include "hal_concepts.hpp"
#include "loop/latency_histogram.hpp"
#include "node/node.hpp"

namespace tread::hal {

/// Sees every frame the loop receives and sends (logging, recording). Must not block or allocate.
struct NoObserver {
  void on_rx(const proto::CanFrame& /*frame*/, std::int64_t /*time_ns*/) noexcept {}
  void on_tx(const proto::CanFrame& /*frame*/, std::int64_t /*time_ns*/) noexcept {}
};

struct LoopConfig {
  std::int64_t period_ns{1'000'000};
  node::Schedule schedule{node::Schedule::periodic};
  std::int64_t sync_poll_ns{20'000};  ///< sync mode: sleep between polls of an empty bus
  /// Sync mode on a bus that can block (hal::WaitableCanBus): the longest single sleep, so that
  /// run() sees a stop request in this time even when the input timeout is long.
  std::int64_t sync_wait_max_ns{50'000'000};
};

struct LoopStats {
  LatencyHistogram wake_latency;  ///< wake time − deadline (periodic mode)
  LatencyHistogram cycle_time;    ///< drain + compute + send
  std::uint64_t cycles{0};
  std::uint64_t overruns{0};
  std::uint64_t tx_failed{0};  ///< sends refused (queue full: counted, never waited for)
  std::uint64_t rx_drained{0};
};

/// The most frames one receive_batch() call of the loop takes (hal::BatchReceiveCanBus).
inline constexpr std::size_t kRxBatchFrames = 32;

template <CanBus Bus, Clock ClockT, OutputPin Pin, typename NodeT, typename Observer = NoObserver>
class LoopRunner {
 public:
  LoopRunner(NodeT& node, Bus& bus, ClockT& clock, Pin& pin, const LoopConfig& config,
             Observer& observer) noexcept
      : node_(node), bus_(bus), clock_(clock), pin_(pin), config_(config), observer_(observer) {}

  /// Periodic mode: the first deadline (CLOCK time). Without it the first deadline is one period
  /// after the first cycle starts. For a rig that must know the node's grid (the threaded demo).
  void set_first_deadline_ns(std::int64_t deadline_ns) noexcept { next_deadline_ns_ = deadline_ns; }

  /// Periodic mode: waits for the next deadline and runs one cycle.
  void run_periodic_cycle() noexcept {
    if (next_deadline_ns_ < 0) {
      next_deadline_ns_ = clock_.now_ns() + config_.period_ns;
    }
    static_cast<void>(clock_.sleep_until_ns(next_deadline_ns_));
    const std::int64_t wake = clock_.now_ns();
    stats_.wake_latency.add_ns(wake - next_deadline_ns_);
    static_cast<void>(pin_.set(true));
    drain(next_deadline_ns_);
    transmit(next_deadline_ns_);
    static_cast<void>(pin_.set(false));
    const std::int64_t done = clock_.now_ns();
    stats_.cycle_time.add_ns(done - wake);
    ++stats_.cycles;
    next_deadline_ns_ += config_.period_ns;
    if (done > next_deadline_ns_) {
      const std::int64_t missed = (done - next_deadline_ns_) / config_.period_ns + 1;
      stats_.overruns += static_cast<std::uint64_t>(missed);
      node_.note_overrun(static_cast<std::uint64_t>(missed));
      next_deadline_ns_ += missed * config_.period_ns;  // stay on the grid: no catch-up burst
    }
  }

  /// Sync mode: drains the bus; computes if the rig's cycle frame arrived (or the input timeout
  /// passed without one), else sleeps one poll interval. Returns true if it computed.
  bool poll_sync() noexcept {
    const std::int64_t now = clock_.now_ns();
    const bool trigger = drain(now);
    if (last_compute_ns_ < 0) {
      last_compute_ns_ = now;
    }
    if (trigger || now - last_compute_ns_ > node_.config().input_timeout_ns) {
      static_cast<void>(pin_.set(true));
      transmit(now);
      static_cast<void>(pin_.set(false));
      stats_.cycle_time.add_ns(clock_.now_ns() - now);
      ++stats_.cycles;
      last_compute_ns_ = now;
      return true;
    }
    if constexpr (WaitableCanBus<Bus>) {
      // Event-driven: sleep until a frame arrives (woken by it) or the input timeout is due.
      const std::int64_t due = last_compute_ns_ + node_.config().input_timeout_ns + 1;
      static_cast<void>(bus_.wait_until_ns(std::min(due, now + config_.sync_wait_max_ns)));
    } else {
      static_cast<void>(clock_.sleep_until_ns(now + config_.sync_poll_ns));
    }
    return false;
  }

  /// Runs until `cycles` computations are done or `stop` becomes true.
  void run(std::uint64_t cycles, const std::atomic<bool>* stop = nullptr) noexcept {
    const std::uint64_t target = stats_.cycles + cycles;
    while (stats_.cycles < target && (stop == nullptr || !stop->load(std::memory_order_relaxed))) {
      if (config_.schedule == node::Schedule::periodic) {
        run_periodic_cycle();
      } else {
        static_cast<void>(poll_sync());
      }
    }
  }

  [[nodiscard]] const LoopStats& stats() const noexcept { return stats_; }

 private:
  bool drain(std::int64_t time_ns) noexcept {
    bool trigger = false;
    if constexpr (BatchReceiveCanBus<Bus>) {
      // What is queued in as few calls as the batch allows: one for a cycle's inputs.
      for (;;) {
        const std::size_t got = bus_.receive_batch(std::span<proto::CanFrame>(rx_));
        for (std::size_t k = 0; k < got; ++k) {
          trigger = take(rx_[k], time_ns) || trigger;
        }
        if (got < rx_.size()) {
          return trigger;
        }
      }
    } else {
      proto::CanFrame frame{};
      while (bus_.receive(frame) == Status::ok) {
        trigger = take(frame, time_ns) || trigger;
      }
      return trigger;
    }
  }

  /// One received frame to the observer and the node; true if it is the rig's cycle frame.
  bool take(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
    ++stats_.rx_drained;
    observer_.on_rx(frame, time_ns);
    return node_.receive(frame, time_ns);
  }

  void transmit(std::int64_t time_ns) noexcept {
    const std::size_t n = node_.compute(time_ns, tx_);
    if constexpr (BatchCanBus<Bus>) {
      // The cycle's frames in one call: one wake-up of a waiting receiver for all of them.
      const std::size_t sent = bus_.send_batch(std::span<const proto::CanFrame>(tx_.data(), n));
      stats_.tx_failed += n - std::min(sent, n);
    } else {
      for (std::size_t k = 0; k < n; ++k) {
        if (bus_.send(tx_[k]) != Status::ok) {
          ++stats_.tx_failed;
        }
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      observer_.on_tx(tx_[k], time_ns);
    }
  }

  NodeT& node_;
  Bus& bus_;
  ClockT& clock_;
  Pin& pin_;
  LoopConfig config_;
  Observer& observer_;
  LoopStats stats_{};
  std::array<proto::CanFrame, node::kMaxTxFrames> tx_{};
  /// Where a BatchReceiveCanBus drains to: a cycle's inputs in one call (a rig sends at most
  /// proto::RigLink::kMaxRigFrames a cycle), a backlog in as many calls as it needs.
  std::array<proto::CanFrame, kRxBatchFrames> rx_{};
  std::int64_t next_deadline_ns_{-1};
  std::int64_t last_compute_ns_{-1};
};

}  // namespace tread::hal
