// Acceptance test of the SocketCAN backend: needs a real vcan0 (FD-capable, mtu 72). Runs natively
// on a kernel with vcan, otherwise inside the VM harness (scripts/vm/run-vcan-test.sh).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "socketcan/socketcan_bus.hpp"

namespace tread::hal {
namespace {

constexpr const char* kInterface = "vcan0";

proto::CanFrame receive_within(SocketCanBus& bus, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  proto::CanFrame frame{};
  while (std::chrono::steady_clock::now() < deadline) {
    const Status s = bus.receive(frame);
    if (s == Status::ok) {
      return frame;
    }
    EXPECT_EQ(s, Status::would_block);
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  ADD_FAILURE() << "no frame within " << limit.count() << " ms";
  return frame;
}

TEST(SocketCanBusVcan, ClassicAndFdFramesCrossBetweenTwoSockets) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, true), Status::ok) << "errno " << tx.last_errno();
  ASSERT_EQ(rx.open(kInterface, true), Status::ok) << "errno " << rx.last_errno();

  proto::CanFrame classic{};
  classic.id = 0x123;
  classic.len = 8;
  for (std::uint8_t i = 0; i < 8; ++i) {
    classic.data[i] = static_cast<std::uint8_t>(0xA0U + i);
  }
  ASSERT_EQ(tx.send(classic), Status::ok);

  proto::CanFrame fd{};
  fd.id = 0x1ABCDE;
  fd.extended = true;
  fd.fd = true;
  fd.bit_rate_switch = true;
  fd.len = 48;
  for (std::uint8_t i = 0; i < 48; ++i) {
    fd.data[i] = static_cast<std::uint8_t>(i * 3U);
  }
  ASSERT_EQ(tx.send(fd), Status::ok);

  const proto::CanFrame got1 = receive_within(rx, std::chrono::milliseconds(1000));
  EXPECT_EQ(got1.id, 0x123U);
  EXPECT_FALSE(got1.extended);
  EXPECT_FALSE(got1.fd);
  ASSERT_EQ(got1.len, 8U);
  for (std::uint8_t i = 0; i < 8; ++i) {
    EXPECT_EQ(got1.data[i], classic.data[i]);
  }
  EXPECT_GT(got1.timestamp_ns, 0) << "kernel timestamp missing";

  const proto::CanFrame got2 = receive_within(rx, std::chrono::milliseconds(1000));
  EXPECT_EQ(got2.id, 0x1ABCDEU);
  EXPECT_TRUE(got2.extended);
  EXPECT_TRUE(got2.fd);
  EXPECT_TRUE(got2.bit_rate_switch);
  ASSERT_EQ(got2.len, 48U);
  for (std::uint8_t i = 0; i < 48; ++i) {
    EXPECT_EQ(got2.data[i], fd.data[i]);
  }
  EXPECT_GE(got2.timestamp_ns, got1.timestamp_ns);

  proto::CanFrame none{};
  EXPECT_EQ(rx.receive(none), Status::would_block);
}

TEST(SocketCanBusVcan, RejectsInvalidLengthsWithoutSending) {
  SocketCanBus bus;
  ASSERT_EQ(bus.open(kInterface, true), Status::ok);
  proto::CanFrame bad{};
  bad.len = 9;  // classic frames carry at most 8 bytes
  EXPECT_EQ(bus.send(bad), Status::invalid_argument);
  bad.fd = true;
  bad.len = 13;  // not a valid FD length
  EXPECT_EQ(bus.send(bad), Status::invalid_argument);
}

TEST(SocketCanBusVcan, KernelFiltersPassOnlyTheRequestedIds) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, true), Status::ok);
  ASSERT_EQ(rx.open(kInterface, true), Status::ok);
  const CanIdFilter filters[] = {{0x100, 0x7F0}};  // 0x100..0x10F
  ASSERT_EQ(rx.set_filters(filters), Status::ok);
  for (const std::uint32_t id : {0x200U, 0x105U, 0x0FFU, 0x10FU}) {
    proto::CanFrame f{};
    f.id = id;
    f.len = 1;
    ASSERT_EQ(tx.send(f), Status::ok);
  }
  EXPECT_EQ(receive_within(rx, std::chrono::milliseconds(1000)).id, 0x105U);
  EXPECT_EQ(receive_within(rx, std::chrono::milliseconds(1000)).id, 0x10FU);
  proto::CanFrame none{};
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(rx.receive(none), Status::would_block);
}

TEST(SocketCanBusVcan, ErrorFramesAreReportedAndTrackBusOff) {
  SocketCanBus injector;
  SocketCanBus rx;
  ASSERT_EQ(injector.open(kInterface, false), Status::ok);
  ASSERT_EQ(rx.open(kInterface, false), Status::ok);
  const CanIdFilter none[] = {{0x7FF, 0x7FF}};  // data frames of no interest
  ASSERT_EQ(rx.set_filters(none), Status::ok);
  proto::CanFrame err{};
  err.error = true;
  err.id = 0x040;  // CAN_ERR_BUSOFF
  err.len = 8;
  ASSERT_EQ(injector.send(err), Status::ok);
  const proto::CanFrame got = receive_within(rx, std::chrono::milliseconds(1000));
  EXPECT_TRUE(got.error);
  EXPECT_EQ(got.id & 0x040U, 0x040U);
  EXPECT_TRUE(rx.bus_off());
  err.id = 0x100;  // CAN_ERR_RESTARTED
  ASSERT_EQ(injector.send(err), Status::ok);
  static_cast<void>(receive_within(rx, std::chrono::milliseconds(1000)));
  EXPECT_FALSE(rx.bus_off());
  EXPECT_EQ(rx.error_frames(), 2U);
}

TEST(SocketCanBusVcan, ReceiveQueueOverflowIsCounted) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, false), Status::ok);
  ASSERT_EQ(rx.open(kInterface, false), Status::ok);
  ASSERT_EQ(rx.set_receive_buffer(1024), Status::ok);  // the kernel doubles it; a few frames fit
  proto::CanFrame f{};
  f.id = 0x321;
  f.len = 8;
  int sent = 0;
  for (int i = 0; i < 2000; ++i) {
    if (tx.send(f) == Status::ok) {
      ++sent;
    }
  }
  ASSERT_GT(sent, 100);
  proto::CanFrame got{};
  int received = 0;
  while (rx.receive(got) == Status::ok) {
    ++received;
  }
  EXPECT_LT(received, sent);
  // The kernel stamps the drop count on frames queued after the drops: one more frame carries it.
  ASSERT_EQ(tx.send(f), Status::ok);
  ASSERT_EQ(receive_within(rx, std::chrono::milliseconds(1000)).id, 0x321U);
  EXPECT_EQ(static_cast<std::uint64_t>(received) + rx.rx_overflows(),
            static_cast<std::uint64_t>(sent))
      << "sent " << sent << " received " << received;
}

TEST(SocketCanBusVcan, UnknownInterfaceIsAClearError) {
  SocketCanBus bus;
  EXPECT_EQ(bus.open("nosuchcan7", false), Status::invalid_argument);
  EXPECT_FALSE(bus.is_open());
}

}  // namespace
}  // namespace tread::hal
