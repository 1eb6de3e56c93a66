#pragma once
// Replaying a node's candump log, one logged frame at a time, with no heap: the host's
// `tread node --replay` and the firmware image run the node through this same schedule.
//
// The node's own frames in the log mark the cycles it ran (every cycle sends NodeStatus); the rest
// are its inputs, logged at the time the node consumed them. Fed in time order, an input is passed
// to receive() at once, and the cycle at time T is computed when the first frame later than T (or
// the end of the log) arrives, so every input logged at or before T is received before the
// computation at T: the run repeats exactly, in periodic and in sync mode alike. In periodic mode,
// deadlines the live run skipped after an overrun (gaps of more than one period between cycles)
// are reported to the node before the next computation, as the live runner did.

#include <array>
#include <cstdint>

#include "core/status.hpp"
#include "node/node.hpp"
#include "proto/messages.hpp"

namespace tread::node {

/// What a replay sees and does.
struct ReplayCounts {
  std::uint64_t cycles{0};            ///< computations run
  std::uint64_t overruns{0};          ///< deadlines the live run missed (periodic mode)
  std::uint64_t input_frames{0};      ///< logged frames passed to receive()
  std::uint64_t logged_tx_frames{0};  ///< node outputs found in the log
  std::uint64_t tx_frames{0};         ///< frames the replayed node transmitted
};

/// Whether a logged frame is one the node sends (in this layout).
inline bool is_node_output(proto::Layout layout, const proto::CanFrame& frame) noexcept {
  const proto::MessageSpec* m = proto::find_message(layout, frame.id);
  return !frame.error && !frame.extended && m != nullptr &&
         m->direction == proto::Direction::node_to_rig;
}

/// A node the replay can drive (node::Node, or a wrapper that measures it).
template <typename N>
concept ReplayableNode = requires(N n, const proto::CanFrame& frame, std::int64_t now_ns,
                                  std::span<proto::CanFrame> tx) {
  { n.receive(frame, now_ns) } -> std::same_as<bool>;
  { n.compute(now_ns, tx) } -> std::same_as<std::size_t>;
  n.note_overrun(std::uint64_t{1});
  { n.config() } -> std::convertible_to<const NodeConfig&>;
};

/// Receives what the replay produces: on_logged_tx(frame, time) for each node output found in the
/// log, on_tx(frame, now) for each frame the replayed node transmits.
template <typename S>
concept ReplaySink = requires(S sink, const proto::CanFrame& frame, std::int64_t time_ns) {
  sink.on_logged_tx(frame, time_ns);
  sink.on_tx(frame, time_ns);
};

template <ReplayableNode N, ReplaySink Sink>
class LogReplay {
 public:
  /// `period_ns`: the live run's cycle period (> 0); `node` and `sink` outlive the replay.
  LogReplay(N& node, Sink& sink, std::int64_t period_ns) noexcept
      : node_(node), sink_(sink), period_ns_(period_ns > 0 ? period_ns : 1) {}

  /// The next logged frame, in the log's order.
  /// @retval Status::ok
  /// @retval Status::out_of_range  earlier than a frame before it: the log is not in time order
  ///                               (nothing was done with the frame)
  Status add(const proto::CanFrame& frame, std::int64_t time_ns) {
    if (any_ && time_ns < last_time_ns_) {
      return Status::out_of_range;
    }
    any_ = true;
    last_time_ns_ = time_ns;
    if (pending_ && time_ns > pending_ns_) {
      run_cycle();
    }
    if (is_node_output(node_.config().layout, frame)) {
      ++counts_.logged_tx_frames;
      sink_.on_logged_tx(frame, time_ns);
      if (!pending_ && (!computed_ || time_ns != last_cycle_ns_)) {
        pending_ = true;
        pending_ns_ = time_ns;
      }
      return Status::ok;
    }
    static_cast<void>(node_.receive(frame, time_ns));
    ++counts_.input_frames;
    return Status::ok;
  }

  /// The end of the log: runs the last cycle.
  void finish() {
    if (pending_) {
      run_cycle();
    }
  }

  [[nodiscard]] const ReplayCounts& counts() const noexcept { return counts_; }

 private:
  void run_cycle() {
    const std::int64_t now = pending_ns_;
    pending_ = false;
    if (node_.config().schedule == Schedule::periodic && computed_) {
      const std::int64_t missed = (now - last_cycle_ns_) / period_ns_ - 1;
      if (missed > 0) {
        node_.note_overrun(static_cast<std::uint64_t>(missed));
        counts_.overruns += static_cast<std::uint64_t>(missed);
      }
    }
    const std::size_t n = node_.compute(now, tx_);
    for (std::size_t i = 0; i < n; ++i) {
      sink_.on_tx(tx_[i], now);
    }
    counts_.tx_frames += n;
    ++counts_.cycles;
    computed_ = true;
    last_cycle_ns_ = now;
  }

  N& node_;
  Sink& sink_;
  std::int64_t period_ns_;
  ReplayCounts counts_{};
  std::array<proto::CanFrame, kMaxTxFrames> tx_{};
  bool any_{false};
  std::int64_t last_time_ns_{0};
  bool pending_{false};
  std::int64_t pending_ns_{0};
  bool computed_{false};
  std::int64_t last_cycle_ns_{0};
};

}  // namespace tread::node
