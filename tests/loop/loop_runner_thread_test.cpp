// The loop on its own thread, event-driven: in sync mode on a bus that can block until a frame
// arrives (hal::WaitableCanBus; here the thread link), the node sleeps until the rig's cycle frame
// and answers it, every time, without polling.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <thread>

#include "loop/loop_runner.hpp"
#include "node/test_channels.hpp"
#include "posix/posix_clock.hpp"
#include "posix/thread_can_link.hpp"
#include "proto/rig_link.hpp"

namespace tread::hal {
namespace {

using testing::LinearContact;
using testing::LinearTyre;

TEST(LoopRunnerThread, SyncModeOnAWaitableBusAnswersEveryCycleFrameOfAnotherThread) {
  constexpr std::uint32_t kCycles = 500;
  // An input timeout far longer than the test: the node computes only on the rig's cycle frames.
  const node::NodeConfig config{.layout = proto::Layout::classic,
                                .wheels = 4,
                                .wheelsets = 2,
                                .input_timeout_ns = 60'000'000'000,
                                .schedule = node::Schedule::sync};
  std::array<LinearTyre, 4> tyres{};
  std::array<LinearContact, 2> contacts{};
  node::Node<LinearTyre, LinearContact> node(config, tyres, contacts);
  auto link = std::make_unique<ThreadCanLink>();
  std::atomic<bool> stop{false};
  LoopStats stats{};
  std::thread node_thread([&] {
    PosixClock clock;
    NoPin pin;
    NoObserver observer;
    LoopRunner loop(node, link->endpoint(0), clock, pin,
                    LoopConfig{1'000'000, node::Schedule::sync, 20'000}, observer);
    loop.run(kCycles, &stop);
    stats = loop.stats();
  });

  proto::RigLink rig(proto::Layout::classic, 4, 2);
  ThreadCanEndpoint& bus = link->endpoint(1);
  PosixClock clock;
  std::uint32_t answered = 0;
  std::uint32_t wrong = 0;
  for (std::uint32_t c = 0; c < kCycles; ++c) {
    proto::RigData d;
    for (auto& w : d.wheels) {
      w = proto::WheelInput{0.05F, 0.01F, 0.0F, 4000.0F, 20.0F, 0.0F, false};
    }
    d.rig_cycle = c;
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = rig.encode_cycle(d, frames);
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(bus.send(frames[k]), Status::ok);
    }
    // The whole answer: 13 frames (status, 4 wheels × 2, 2 wheelsets × 2).
    proto::NodeData out{};
    std::size_t got = 0;
    proto::CanFrame f{};
    while (got < 13U) {
      if (bus.receive(f) == Status::ok) {
        got += rig.receive(f, out) == Status::ok ? 1U : 0U;
      } else {
        ASSERT_EQ(bus.wait_until_ns(clock.now_ns() + 60'000'000'000), Status::ok);
      }
    }
    ++answered;
    wrong += std::abs(out.wheels[0].fx_n - 50.0F) <= 0.5F ? 0U : 1U;
  }
  node_thread.join();
  EXPECT_EQ(answered, kCycles);
  EXPECT_EQ(wrong, 0U);
  EXPECT_EQ(stats.cycles, kCycles);  // one computation per cycle frame, none of its own
  // The rig drains each frame as it comes and sleeps again until the answer is whole; the node's
  // 13 frames a cycle still cost its thread one wake-up call at most (the loop sends them as one
  // batch), not one per frame.
  EXPECT_LE(link->endpoint(0).wake_calls(), std::uint64_t{kCycles});
  EXPECT_EQ(stats.tx_failed, 0U);
  EXPECT_EQ(node.counters().rx_rejected(), 0U);
  EXPECT_EQ(node.counters().stale_events, 0U);
}

}  // namespace
}  // namespace tread::hal
