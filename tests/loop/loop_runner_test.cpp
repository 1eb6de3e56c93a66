#include "loop/loop_runner.hpp"

#include <gtest/gtest.h>

#include <array>

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

struct LoopHarness {
  explicit LoopHarness(node::Schedule schedule, proto::Layout layout = proto::Layout::classic)
      : node_config{layout, 4, 2, 10 * kMs, schedule, true, 3},
        node(node_config, tyres, contacts),
        loop(node, net.endpoint(0), clock, pin, LoopConfig{kMs, schedule, 20'000}, observer),
        rig(layout, 4, 2) {}

  void rig_sends(std::uint32_t rig_cycle) {
    proto::RigData d;
    for (auto& w : d.wheels) {
      w = proto::WheelInput{0.05F, 0.01F, 0.0F, 4000.0F, 20.0F, 0.0F, false};
    }
    d.rig_cycle = rig_cycle;
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = rig.encode_cycle(d, frames);
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(net.endpoint(1).send(frames[k]), Status::ok);
    }
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
  FakeGpio<SimClock, 1024> pin{clock};
  NoObserver observer;
  node::NodeConfig node_config;
  std::array<LinearTyre, 4> tyres{};
  std::array<LinearContact, 2> contacts{};
  node::Node<LinearTyre, LinearContact> node;
  LoopRunner<StubCanEndpoint, SimClock, FakeGpio<SimClock, 1024>, decltype(node)> loop;
  proto::RigLink rig;
};

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

}  // namespace
}  // namespace tread::hal
