#include "stub/stub_can_bus.hpp"

#include <gtest/gtest.h>

#include "hal_concepts.hpp"
#include "stub/fake_gpio.hpp"
#include "stub/sim_clock.hpp"

namespace tread::hal {
namespace {

static_assert(CanBus<StubCanEndpoint>);
static_assert(Clock<SimClock>);
static_assert(OutputPin<FakeGpio<SimClock>>);

proto::CanFrame frame(std::uint32_t id, std::uint8_t first_byte = 0) {
  proto::CanFrame f{};
  f.id = id;
  f.len = 8;
  f.data[0] = first_byte;
  return f;
}

struct StubBusTest : ::testing::Test {
  SimClock clock{1'000'000};
  StubCanNetwork net{&clock_now<SimClock>, &clock};
  StubCanEndpoint& a = net.endpoint(0);
  StubCanEndpoint& b = net.endpoint(1);
  StubCanEndpoint& c = net.endpoint(2);
};

TEST_F(StubBusTest, EveryOtherEndpointSeesAFrameOnceInOrder) {
  ASSERT_EQ(a.send(frame(0x10, 1)), Status::ok);
  ASSERT_EQ(a.send(frame(0x11, 2)), Status::ok);
  proto::CanFrame got{};
  for (StubCanEndpoint* e : {&b, &c}) {
    ASSERT_EQ(e->receive(got), Status::ok);
    EXPECT_EQ(got.id, 0x10U);
    EXPECT_EQ(got.timestamp_ns, 1'000'000);
    ASSERT_EQ(e->receive(got), Status::ok);
    EXPECT_EQ(got.id, 0x11U);
    EXPECT_EQ(e->receive(got), Status::would_block);
  }
  EXPECT_EQ(a.receive(got), Status::would_block);  // no echo to the sender
}

TEST_F(StubBusTest, DropNextLosesFramesSilently) {
  net.faults().drop_next = 2;
  for (std::uint8_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.send(frame(0x20, i)), Status::ok);
  }
  proto::CanFrame got{};
  ASSERT_EQ(b.receive(got), Status::ok);
  EXPECT_EQ(got.data[0], 2U);
  EXPECT_EQ(b.receive(got), Status::would_block);
  EXPECT_EQ(net.frames_dropped(), 2U);
}

TEST_F(StubBusTest, ProbabilisticDropIsDeterministicAndNearItsRate) {
  net.faults().drop_probability = 0.25;
  for (int i = 0; i < 400; ++i) {
    static_cast<void>(a.send(frame(0x21)));
    proto::CanFrame got{};
    while (b.receive(got) == Status::ok) {
    }
  }
  EXPECT_GT(net.frames_dropped(), 70U);
  EXPECT_LT(net.frames_dropped(), 130U);
  StubCanNetwork again;
  again.faults().drop_probability = 0.25;
  for (int i = 0; i < 400; ++i) {
    static_cast<void>(again.endpoint(0).send(frame(0x21)));
    proto::CanFrame got{};
    while (again.endpoint(1).receive(got) == Status::ok) {
    }
  }
  EXPECT_EQ(again.frames_dropped(), net.frames_dropped());
}

TEST_F(StubBusTest, CorruptionFlipsExactlyOneBit) {
  net.faults().corrupt_next = 1;
  proto::CanFrame sent = frame(0x30);
  for (std::uint8_t i = 0; i < 8; ++i) {
    sent.data[i] = static_cast<std::uint8_t>(0x11U * i);
  }
  ASSERT_EQ(a.send(sent), Status::ok);
  proto::CanFrame got{};
  ASSERT_EQ(b.receive(got), Status::ok);
  int flipped = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    flipped += __builtin_popcount(static_cast<unsigned>(got.data[i] ^ sent.data[i]));
  }
  EXPECT_EQ(flipped, 1);
}

TEST_F(StubBusTest, DelayedFramesArriveWhenDue) {
  net.faults().delay_ns = 500'000;
  ASSERT_EQ(a.send(frame(0x40)), Status::ok);
  proto::CanFrame got{};
  EXPECT_EQ(b.receive(got), Status::would_block);
  clock.advance_ns(499'999);
  EXPECT_EQ(b.receive(got), Status::would_block);
  clock.advance_ns(1);
  ASSERT_EQ(b.receive(got), Status::ok);
  EXPECT_EQ(got.timestamp_ns, 1'500'000);
}

TEST_F(StubBusTest, BusOffRefusesSendsUntilRestartAndReportsErrorFrames) {
  net.set_bus_off();
  EXPECT_EQ(a.send(frame(0x50)), Status::io_error);
  proto::CanFrame got{};
  ASSERT_EQ(b.receive(got), Status::ok);
  EXPECT_TRUE(got.error);
  EXPECT_EQ(got.id, kErrBusOff);
  net.restart();
  ASSERT_EQ(b.receive(got), Status::ok);
  EXPECT_EQ(got.id, kErrRestarted);
  EXPECT_EQ(a.send(frame(0x50)), Status::ok);
  net.inject_error_frame(kErrCtrl);
  ASSERT_EQ(c.receive(got), Status::ok);  // c: bus-off, restarted, then the data frame ...
  ASSERT_EQ(c.receive(got), Status::ok);
  ASSERT_EQ(c.receive(got), Status::ok);
  EXPECT_EQ(got.id, 0x50U);
  ASSERT_EQ(c.receive(got), Status::ok);  // ... then the controller error
  EXPECT_TRUE(got.error);
  EXPECT_EQ(got.id, kErrCtrl);
}

TEST_F(StubBusTest, FullQueueCountsOverflowsAndInvalidLengthsAreRefused) {
  for (std::size_t i = 0; i < kStubQueueFrames + 5; ++i) {
    ASSERT_EQ(a.send(frame(0x60)), Status::ok);
  }
  EXPECT_EQ(b.queued(), kStubQueueFrames);
  EXPECT_EQ(b.rx_overflows(), 5U);
  proto::CanFrame bad = frame(0x61);
  bad.len = 9;
  EXPECT_EQ(a.send(bad), Status::invalid_argument);
  bad.fd = true;
  bad.len = 33;
  EXPECT_EQ(a.send(bad), Status::invalid_argument);
}

TEST(SimClockTest, SleepsJumpForwardNeverBackAndAddLatency) {
  SimClock clock(100);
  EXPECT_EQ(clock.sleep_until_ns(1000), Status::ok);
  EXPECT_EQ(clock.now_ns(), 1000);
  EXPECT_EQ(clock.sleep_until_ns(500), Status::ok);
  EXPECT_EQ(clock.now_ns(), 1000);
  clock.set_wake_latency_ns(7);
  EXPECT_EQ(clock.sleep_until_ns(2000), Status::ok);
  EXPECT_EQ(clock.now_ns(), 2007);
}

TEST(FakeGpioTest, RecordsEdgesWithTimes) {
  SimClock clock(0);
  FakeGpio<SimClock, 4> pin(clock);
  EXPECT_EQ(pin.set(false), Status::ok);  // no edge: already low
  clock.advance_ns(10);
  EXPECT_EQ(pin.set(true), Status::ok);
  clock.advance_ns(5);
  EXPECT_EQ(pin.set(true), Status::ok);
  EXPECT_EQ(pin.set(false), Status::ok);
  ASSERT_EQ(pin.edge_count(), 2U);
  EXPECT_EQ(pin.edge(0).time_ns, 10);
  EXPECT_TRUE(pin.edge(0).level);
  EXPECT_EQ(pin.edge(1).time_ns, 15);
  EXPECT_FALSE(pin.edge(1).level);
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(pin.set(i % 2 == 0), Status::ok);
  }
  EXPECT_EQ(pin.edge_count(), 12U);  // counted past capacity, stored up to it
}

}  // namespace
}  // namespace tread::hal
