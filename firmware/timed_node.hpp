#pragma once
// Wraps the node for the replay and measures each compute() in SysTick ticks (instructions under
// qemu's -icount: hal/cortex_m/systick_counter.hpp). Cycles in which every configured channel was
// computed (none stale, node enabled) are counted apart: that is the node cycle's real cost.
// receive() is measured too, per frame.

#include <cstdint>
#include <span>

#include "cortex_m/systick_counter.hpp"
#include "node/node.hpp"

namespace tread::firmware {

struct TickStats {
  std::uint64_t count{0};
  std::uint64_t total{0};
  std::uint32_t min{0xFFFFFFFFU};
  std::uint32_t max{0};
  void add(std::uint32_t ticks) noexcept {
    ++count;
    total += ticks;
    min = ticks < min ? ticks : min;
    max = ticks > max ? ticks : max;
  }
};

template <typename N>
class TimedNode {
 public:
  TimedNode(N& node, hal::SysTickCounter& counter) noexcept : node_(node), counter_(counter) {}

  bool receive(const proto::CanFrame& frame, std::int64_t now_ns) noexcept {
    const std::uint32_t start = counter_.ticks();
    const bool cycle_frame = node_.receive(frame, now_ns);
    receive_.add(counter_.ticks() - start);
    return cycle_frame;
  }
  std::size_t compute(std::int64_t now_ns, std::span<proto::CanFrame> tx) noexcept {
    const std::uint32_t start = counter_.ticks();
    const std::size_t n = node_.compute(now_ns, tx);
    const std::uint32_t ticks = counter_.ticks() - start;
    all_.add(ticks);
    if (node_.enabled() && node_.outputs().status.stale_mask == 0U) {
      full_.add(ticks);
    }
    return n;
  }
  void note_overrun(std::uint64_t missed) noexcept { node_.note_overrun(missed); }
  [[nodiscard]] const node::NodeConfig& config() const noexcept { return node_.config(); }

  [[nodiscard]] const TickStats& all_cycles() const noexcept { return all_; }
  [[nodiscard]] const TickStats& full_cycles() const noexcept { return full_; }
  /// Per received frame (validation, E2E check, decode); a frame is a few ticks, so read the mean.
  [[nodiscard]] const TickStats& receives() const noexcept { return receive_; }

 private:
  N& node_;
  hal::SysTickCounter& counter_;
  TickStats all_{};
  TickStats full_{};
  TickStats receive_{};
};

}  // namespace tread::firmware
