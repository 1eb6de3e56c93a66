// Acceptance test of the SocketCAN backend: needs a real vcan0 (FD-capable, mtu 72). Runs natively
// on a kernel with vcan, otherwise inside the VM harness (scripts/vm/run-vcan-test.sh).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

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

/// Takes `count` frames from `bus` with receive_batch() in calls of at most `per_call`, within a
/// second; fails if more come or the calls return more than asked for.
std::vector<proto::CanFrame> receive_batches(SocketCanBus& bus, std::size_t count,
                                             std::size_t per_call) {
  std::vector<proto::CanFrame> got;
  std::vector<proto::CanFrame> buffer(per_call);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (got.size() < count && std::chrono::steady_clock::now() < deadline) {
    const std::size_t n = bus.receive_batch(buffer);
    EXPECT_LE(n, per_call);
    got.insert(got.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
    if (n == 0) {
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
  }
  EXPECT_EQ(got.size(), count);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(bus.receive_batch(buffer), 0U) << "more frames than were sent";
  return got;
}

TEST(SocketCanBusVcan, BatchesCrossInOrderWithEveryKindOfFrameAndTheirTimestamps) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, true), Status::ok) << "errno " << tx.last_errno();
  ASSERT_EQ(rx.open(kInterface, true), Status::ok) << "errno " << rx.last_errno();
  // More than one system call's worth (kBatchFrames), classic, 29-bit and FD frames mixed.
  constexpr std::size_t kCount = 2 * SocketCanBus::kBatchFrames + 7;
  std::vector<proto::CanFrame> sent(kCount);
  for (std::size_t i = 0; i < kCount; ++i) {
    proto::CanFrame& f = sent[i];
    f.id = static_cast<std::uint32_t>(0x100 + i);
    f.extended = i % 3 == 1;
    if (f.extended) {
      f.id |= 0x1A00000U;
    }
    f.fd = i % 3 == 2;
    f.bit_rate_switch = f.fd && i % 2 == 0;
    f.len = f.fd ? std::array<std::uint8_t, 4>{12, 20, 48, 64}[i % 4]
                 : static_cast<std::uint8_t>(i % 9);
    for (std::uint8_t b = 0; b < f.len; ++b) {
      f.data[b] = static_cast<std::uint8_t>(i * 7U + b);
    }
  }
  const auto before = std::chrono::system_clock::now().time_since_epoch();
  ASSERT_EQ(tx.send_batch(sent), kCount) << "errno " << tx.last_errno();
  EXPECT_EQ(tx.tx_dropped(), 0U);
  EXPECT_EQ(tx.send_batch(std::span<const proto::CanFrame>()), 0U);

  const std::vector<proto::CanFrame> got = receive_batches(rx, kCount, 10);
  ASSERT_EQ(got.size(), kCount);
  const std::int64_t since_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(before).count();
  for (std::size_t i = 0; i < kCount; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(got[i].id, sent[i].id);
    EXPECT_EQ(got[i].extended, sent[i].extended);
    EXPECT_EQ(got[i].fd, sent[i].fd);
    EXPECT_EQ(got[i].bit_rate_switch, sent[i].bit_rate_switch);
    EXPECT_FALSE(got[i].error);
    ASSERT_EQ(got[i].len, sent[i].len);
    EXPECT_TRUE(
        std::equal(got[i].data.begin(), got[i].data.begin() + got[i].len, sent[i].data.begin()));
    // Each frame its own kernel receive time (CLOCK_REALTIME), in order.
    EXPECT_GE(got[i].timestamp_ns, since_ns);
    if (i > 0) {
      EXPECT_GE(got[i].timestamp_ns, got[i - 1].timestamp_ns);
    }
  }
  EXPECT_EQ(rx.rx_malformed(), 0U);
}

TEST(SocketCanBusVcan, ABatchStopsAtTheFirstFrameTheSocketCannotSend) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, false), Status::ok);  // classic only: FD frames are refused
  ASSERT_EQ(rx.open(kInterface, true), Status::ok);
  std::array<proto::CanFrame, 4> frames{};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    frames[i].id = static_cast<std::uint32_t>(0x301 + i);
    frames[i].len = 2;
  }
  frames[2].fd = true;
  frames[2].len = 12;
  EXPECT_EQ(tx.send_batch(frames), 2U);  // the two before the FD frame; not the one after it
  EXPECT_EQ(tx.tx_dropped(), 0U);        // refused as invalid, not for a full queue
  const std::vector<proto::CanFrame> got = receive_batches(rx, 2, 8);
  ASSERT_EQ(got.size(), 2U);
  EXPECT_EQ(got[0].id, 0x301U);
  EXPECT_EQ(got[1].id, 0x302U);

  frames[0].len = 9;  // no classic frame has 9 bytes: nothing goes
  EXPECT_EQ(tx.send_batch(frames), 0U);
  static_cast<void>(receive_batches(rx, 0, 8));
}

TEST(SocketCanBusVcan, BatchReceiveTracksErrorFramesAndCountsOverflows) {
  SocketCanBus tx;
  SocketCanBus rx;
  ASSERT_EQ(tx.open(kInterface, false), Status::ok);
  ASSERT_EQ(rx.open(kInterface, false), Status::ok);
  proto::CanFrame err{};
  err.error = true;
  err.id = 0x040;  // CAN_ERR_BUSOFF
  err.len = 8;
  ASSERT_EQ(tx.send(err), Status::ok);
  std::vector<proto::CanFrame> got = receive_batches(rx, 1, 4);
  ASSERT_EQ(got.size(), 1U);
  EXPECT_TRUE(got[0].error);
  EXPECT_EQ(got[0].id & 0x040U, 0x040U);
  EXPECT_TRUE(rx.bus_off());
  err.id = 0x100;  // CAN_ERR_RESTARTED
  ASSERT_EQ(tx.send(err), Status::ok);
  got = receive_batches(rx, 1, 4);
  EXPECT_FALSE(rx.bus_off());
  EXPECT_EQ(rx.error_frames(), 2U);

  // The kernel's drop count, carried by the frames queued after the drops, read in batches too.
  ASSERT_EQ(rx.set_receive_buffer(1024), Status::ok);
  proto::CanFrame f{};
  f.id = 0x321;
  f.len = 8;
  const std::vector<proto::CanFrame> burst(2000, f);
  const std::size_t sent = tx.send_batch(burst);
  ASSERT_GT(sent, 100U);
  std::array<proto::CanFrame, 16> buffer{};
  std::size_t received = 0;
  for (std::size_t n = rx.receive_batch(buffer); n > 0; n = rx.receive_batch(buffer)) {
    received += n;
  }
  EXPECT_LT(received, sent);
  ASSERT_EQ(tx.send(f), Status::ok);
  received += receive_batches(rx, 1, 16).size();
  EXPECT_EQ(received + rx.rx_overflows(), sent + 1U) << "sent " << sent << " received " << received;
}

TEST(SocketCanBusVcan, BatchesOnAClosedBusDoNothing) {
  SocketCanBus bus;
  std::array<proto::CanFrame, 3> frames{};
  EXPECT_EQ(bus.send_batch(frames), 0U);
  EXPECT_EQ(bus.receive_batch(frames), 0U);
  EXPECT_EQ(bus.tx_dropped(), 0U);
}

TEST(SocketCanBusVcan, UnknownInterfaceIsAClearError) {
  SocketCanBus bus;
  EXPECT_EQ(bus.open("nosuchcan7", false), Status::invalid_argument);
  EXPECT_FALSE(bus.is_open());
}

}  // namespace
}  // namespace tread::hal
