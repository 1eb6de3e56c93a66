#include "loop/loop_runner.hpp"

#include <gtest/gtest.h>

#include <array>
#include <span>

#include "node/test_channels.hpp"
#include "proto/rig_link.hpp"
#include "stub/fake_gpio.hpp"
#include "stub/sim_clock.hpp"
#include "stub/stub_can_bus.hpp"

namespace tread::hal {
namespace {

using testing::LinearContact;
using testing::LinearTyre;
constexpr std::int64_t kMs = 1'000'000;

/// The node's end of the stub bus, a frame a call (hal::CanBus), counting the loop's calls.
struct FrameByFrameBus {
  explicit FrameByFrameBus(StubCanEndpoint& endpoint) noexcept : end(endpoint) {}
  StubCanEndpoint& end;
  std::size_t receive_calls{0};
  Status send(const proto::CanFrame& frame) noexcept { return end.send(frame); }
  Status receive(proto::CanFrame& frame) noexcept {
    ++receive_calls;
    return end.receive(frame);
  }
};
static_assert(!BatchReceiveCanBus<FrameByFrameBus>);

/// The same end taking what is queued in batches as well (hal::BatchReceiveCanBus), as SocketCAN's
/// recvmmsg does.
struct BatchReceivingBus : FrameByFrameBus {
  using FrameByFrameBus::FrameByFrameBus;
  std::size_t batch_calls{0};
  std::size_t receive_batch(std::span<proto::CanFrame> frames) noexcept {
    ++batch_calls;
    std::size_t n = 0;
    while (n < frames.size() && end.receive(frames[n]) == Status::ok) {
      ++n;
    }
    return n;
  }
};
static_assert(BatchReceiveCanBus<BatchReceivingBus>);

template <typename Bus>
struct BasicLoopHarness {
  explicit BasicLoopHarness(node::Schedule schedule, proto::Layout layout = proto::Layout::classic)
      : node_config{layout, 4, 2, 10 * kMs, schedule, true, 3},
        node(node_config, tyres, contacts),
        loop(node, bus, clock, pin, LoopConfig{kMs, schedule, 20'000}, observer),
        rig(layout, 4, 2) {}

  /// The rig's frames of one cycle; returns how many.
  std::size_t rig_sends(std::uint32_t rig_cycle) {
    proto::RigData d;
    for (auto& w : d.wheels) {
      w = proto::WheelInput{0.05F, 0.01F, 0.0F, 4000.0F, 20.0F, 0.0F, false};
    }
    d.rig_cycle = rig_cycle;
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = rig.encode_cycle(d, frames);
    for (std::size_t k = 0; k < n; ++k) {
      EXPECT_EQ(net.endpoint(1).send(frames[k]), Status::ok);
    }
    return n;
  }

  std::size_t rig_receives(proto::NodeData& out) {
    std::size_t n = 0;
    proto::CanFrame f{};
    while (net.endpoint(1).receive(f) == Status::ok) {
      if (rig.receive(f, out) == Status::ok) {
        ++n;
      }
    }
    return n;
  }

  SimClock clock{0};
  StubCanNetwork net{&clock_now<SimClock>, &clock};
  Bus bus{net.endpoint(0)};
  FakeGpio<SimClock, 1024> pin{clock};
  NoObserver observer;
  node::NodeConfig node_config;
  std::array<LinearTyre, 4> tyres{};
  std::array<LinearContact, 2> contacts{};
  node::Node<LinearTyre, LinearContact> node;
  LoopRunner<Bus, SimClock, FakeGpio<SimClock, 1024>, decltype(node)> loop;
  proto::RigLink rig;
};
using LoopHarness = BasicLoopHarness<FrameByFrameBus>;

TEST(LoopRunner, PeriodicCyclesRunOnAbsoluteDeadlinesWithoutDrift) {
  LoopHarness h(node::Schedule::periodic);
  h.clock.set_wake_latency_ns(30'000);  // every wake-up 30 µs late: must not accumulate
  for (std::uint32_t c = 0; c < 100; ++c) {
    h.rig_sends(c);
    h.loop.run_periodic_cycle();
    proto::NodeData out{};
    EXPECT_EQ(h.rig_receives(out), 13U);
    EXPECT_NEAR(out.wheels[0].fx_n, 50.0F, 0.5F);
  }
  ASSERT_EQ(h.pin.edge_count(), 200U);
  for (std::size_t k = 0; k < 100; ++k) {
    // Rising edge at deadline k+1 plus the wake latency: on the grid, no drift.
    EXPECT_EQ(h.pin.edge(2 * k).time_ns, static_cast<std::int64_t>(k + 1) * kMs + 30'000);
    EXPECT_TRUE(h.pin.edge(2 * k).level);
  }
  EXPECT_EQ(h.loop.stats().overruns, 0U);
  EXPECT_EQ(h.loop.stats().wake_latency.percentile_us(0.5), 30);
  EXPECT_EQ(h.node.counters().rx_rejected(), 0U);
  EXPECT_EQ(h.node.counters().rx_accepted, 100U * 11U);
}

TEST(LoopRunner, OverrunsAreCountedReportedAndSkipped) {
  LoopHarness h(node::Schedule::periodic);
  h.clock.set_wake_latency_ns(2'500'000);  // each cycle ends 2.5 ms after its deadline
  for (std::uint32_t c = 0; c < 4; ++c) {
    h.rig_sends(c);
    h.loop.run_periodic_cycle();
  }
  // Deadlines 1, (2,3 missed) 4, (5,6) 7, ...: two missed per cycle, and the grid is kept.
  EXPECT_EQ(h.loop.stats().overruns, 8U);
  EXPECT_EQ(h.node.counters().overruns, 8U);
  EXPECT_EQ(h.pin.edge(2).time_ns, 4 * kMs + 2'500'000);
  proto::NodeData out{};
  h.rig_receives(out);
  EXPECT_EQ(out.status.overruns, 6U);  // reported in the last status frame (before the last skip)
  EXPECT_NE(out.status.state & proto::kNodeOverrun, 0U);
}

TEST(LoopRunner, SyncModeComputesWhenTheRigCycleFrameArrives) {
  LoopHarness h(node::Schedule::sync);
  std::uint64_t computed = 0;
  for (std::uint32_t c = 0; c < 20; ++c) {
    h.rig_sends(c);
    for (int poll = 0; poll < 100; ++poll) {  // 100 polls of 20 µs = 2 ms between rig cycles
      computed += h.loop.poll_sync() ? 1U : 0U;
    }
  }
  EXPECT_EQ(computed, 20U);
  proto::NodeData out{};
  h.rig_receives(out);
  EXPECT_EQ(out.status.state & proto::kNodeSyncMode, proto::kNodeSyncMode);
  EXPECT_EQ(out.status.stale_mask, 0U);
}

TEST(LoopRunner, SyncModeWithoutTheRigStillReportsStaleOutputs) {
  LoopHarness h(node::Schedule::sync);
  h.rig_sends(0);
  EXPECT_TRUE(h.loop.poll_sync());
  std::uint64_t computed = 0;
  for (int poll = 0; poll < 1200; ++poll) {  // 24 ms of silence
    computed += h.loop.poll_sync() ? 1U : 0U;
  }
  EXPECT_GE(computed, 2U);
  proto::NodeData out{};
  h.rig_receives(out);
  EXPECT_EQ(out.status.stale_mask, 0x3FU);
  EXPECT_EQ(out.wheels[0].fx_n, 0.0F);
}

TEST(LoopRunner, FaultsOnTheBusAreRejectedCountedAndSurvived) {
  LoopHarness h(node::Schedule::periodic);
  for (std::uint32_t c = 0; c < 200; ++c) {
    if (c == 50) {
      h.net.faults().corrupt_next = 5;
    }
    if (c == 100) {
      h.net.faults().drop_next = 3;
    }
    if (c == 150) {
      h.net.set_bus_off();
    }
    if (c == 165) {
      h.net.restart();
    }
    if (c < 150 || c >= 165) {
      h.rig_sends(c);
    }
    h.loop.run_periodic_cycle();
  }
  const node::NodeCounters& n = h.node.counters();
  EXPECT_EQ(n.rx_bad_crc, 5U);
  EXPECT_GE(n.lost_frames, 3U);
  EXPECT_EQ(n.rx_error_frames, 2U);  // bus-off and restarted
  EXPECT_GT(n.stale_events, 0U);     // 15 ms of bus-off: the inputs went stale ...
  proto::NodeData out{};
  h.rig_receives(out);
  EXPECT_EQ(out.status.stale_mask, 0U);  // ... and recovered
  EXPECT_EQ(h.loop.stats().cycles, 200U);
  EXPECT_EQ(h.loop.stats().tx_failed, 13U * 15U);  // the node's sends during bus-off
}

TEST(LoopRunner, OnABusThatTakesBatchesACycleIsDrainedInOneCallWithTheSameAnswers) {
  // The same cycles on both kinds of bus: the node sees the same frames, answers the same.
  for (const node::Schedule schedule : {node::Schedule::periodic, node::Schedule::sync}) {
    LoopHarness frame_by_frame(schedule);
    BasicLoopHarness<BatchReceivingBus> batched(schedule);
    std::uint64_t computed = 0;
    for (std::uint32_t c = 0; c < 50; ++c) {
      const std::size_t sent = frame_by_frame.rig_sends(c);
      ASSERT_EQ(batched.rig_sends(c), sent);
      ASSERT_LT(sent, kRxBatchFrames);
      const std::size_t calls_before = batched.bus.batch_calls;
      if (schedule == node::Schedule::periodic) {
        frame_by_frame.loop.run_periodic_cycle();
        batched.loop.run_periodic_cycle();
      } else {
        ASSERT_TRUE(frame_by_frame.loop.poll_sync());
        ASSERT_TRUE(batched.loop.poll_sync());
      }
      ++computed;
      // One call took the cycle's frames and found nothing more: no call to find the queue empty.
      EXPECT_EQ(batched.bus.batch_calls - calls_before, 1U) << "cycle " << c;
      proto::NodeData a{};
      proto::NodeData b{};
      ASSERT_EQ(frame_by_frame.rig_receives(a), 13U);
      ASSERT_EQ(batched.rig_receives(b), 13U);
      EXPECT_EQ(a.wheels[0].fx_n, b.wheels[0].fx_n);
      EXPECT_EQ(a.wheels[3].fy_n, b.wheels[3].fy_n);
      EXPECT_EQ(a.status.stale_mask, b.status.stale_mask);
      EXPECT_EQ(a.status.state, b.status.state);
    }
    EXPECT_EQ(batched.bus.receive_calls, 0U);  // never a frame at a time
    // The frame-by-frame loop also asked once more a cycle, to find the queue empty.
    EXPECT_EQ(frame_by_frame.loop.stats().rx_drained + computed, frame_by_frame.bus.receive_calls);
    EXPECT_EQ(batched.loop.stats().rx_drained, frame_by_frame.loop.stats().rx_drained);
    EXPECT_EQ(batched.node.counters().rx_bad_crc, 0U);
    EXPECT_EQ(batched.node.counters().lost_frames, frame_by_frame.node.counters().lost_frames);
  }
}

TEST(LoopRunner, ABacklogLongerThanABatchIsDrainedInOneCycle) {
  BasicLoopHarness<BatchReceivingBus> h(node::Schedule::periodic);
  std::size_t queued = 0;
  for (std::uint32_t c = 0; c < 5; ++c) {  // five cycles' frames waiting (a stalled node)
    queued += h.rig_sends(c);
  }
  ASSERT_GT(queued, kRxBatchFrames);
  h.loop.run_periodic_cycle();
  EXPECT_EQ(h.loop.stats().rx_drained, queued);
  // Full batches while there was more, then the one that found the rest.
  EXPECT_EQ(h.bus.batch_calls, queued / kRxBatchFrames + 1U);
  EXPECT_EQ(h.net.endpoint(0).queued(), 0U);
}

}  // namespace
}  // namespace tread::hal
