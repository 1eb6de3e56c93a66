#include "posix/thread_can_link.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>

#include "posix/posix_clock.hpp"

namespace tread::hal {
namespace {

proto::CanFrame frame(std::uint32_t id, std::uint8_t byte) {
  proto::CanFrame f;
  f.id = id;
  f.len = 1;
  f.data[0] = byte;
  return f;
}

TEST(ThreadCanLink, EachEndReceivesWhatTheOtherSendsStampedWithTheMonotonicClock) {
  auto link = std::make_unique<ThreadCanLink>();
  ThreadCanEndpoint& a = link->endpoint(0);
  ThreadCanEndpoint& b = link->endpoint(1);
  PosixClock clock;
  const std::int64_t before = clock.now_ns();
  ASSERT_EQ(a.send(frame(0x100, 1)), Status::ok);
  ASSERT_EQ(b.send(frame(0x200, 2)), Status::ok);
  const std::int64_t after = clock.now_ns();
  proto::CanFrame f{};
  ASSERT_EQ(b.receive(f), Status::ok);
  EXPECT_EQ(f.id, 0x100U);
  EXPECT_EQ(f.data[0], 1U);
  EXPECT_GE(f.timestamp_ns, before);
  EXPECT_LE(f.timestamp_ns, after);
  EXPECT_EQ(b.receive(f), Status::would_block);  // not its own frame
  ASSERT_EQ(a.receive(f), Status::ok);
  EXPECT_EQ(f.id, 0x200U);
  EXPECT_EQ(a.receive(f), Status::would_block);
}

TEST(ThreadCanLink, AFullQueueRefusesAndCountsTheFrame) {
  auto link = std::make_unique<ThreadCanLink>();
  for (std::size_t i = 0; i < kThreadLinkFrames; ++i) {
    ASSERT_EQ(link->endpoint(0).send(frame(1, 0)), Status::ok);
  }
  EXPECT_EQ(link->endpoint(0).send(frame(2, 0)), Status::would_block);
  EXPECT_EQ(link->endpoint(0).tx_dropped(), 1U);
}

TEST(ThreadCanLink, WaitReturnsAtOnceWhenAFrameIsQueuedAndAfterTheDeadlineWhenNone) {
  auto link = std::make_unique<ThreadCanLink>();
  PosixClock clock;
  const std::int64_t deadline = clock.now_ns() + 2'000'000;
  EXPECT_EQ(link->endpoint(1).wait_until_ns(deadline), Status::would_block);
  EXPECT_GE(clock.now_ns(), deadline);  // it slept until the deadline, not less
  ASSERT_EQ(link->endpoint(0).send(frame(1, 0)), Status::ok);
  EXPECT_EQ(link->endpoint(1).wait_until_ns(clock.now_ns() + 60'000'000'000), Status::ok);
}

// A sleeping end is woken by the other thread's frame: a ping-pong of many frames, each end
// waiting with a deadline far away, completes (no lost wake-up would leave an end asleep).
TEST(ThreadCanLink, ASleepingEndIsWokenByEveryFrameOfTheOtherThread) {
  auto link = std::make_unique<ThreadCanLink>();
  constexpr std::uint32_t kRounds = 20'000;
  constexpr std::int64_t kFar = 60'000'000'000;  // a lost wake-up would show as a 60 s hang
  PosixClock clock;
  std::atomic<std::uint32_t> echoed{0};
  std::thread echo([&] {
    ThreadCanEndpoint& b = link->endpoint(1);
    proto::CanFrame f{};
    for (std::uint32_t i = 0; i < kRounds; ++i) {
      while (b.receive(f) != Status::ok) {
        ASSERT_EQ(b.wait_until_ns(clock.now_ns() + kFar), Status::ok);
      }
      f.id += 1;
      ASSERT_EQ(b.send(f), Status::ok);
      echoed.fetch_add(1);
    }
  });
  ThreadCanEndpoint& a = link->endpoint(0);
  proto::CanFrame f{};
  std::uint32_t wrong = 0;
  for (std::uint32_t i = 0; i < kRounds; ++i) {
    ASSERT_EQ(a.send(frame(i & 0x3FFU, 0)), Status::ok);
    while (a.receive(f) != Status::ok) {
      ASSERT_EQ(a.wait_until_ns(clock.now_ns() + kFar), Status::ok);
    }
    wrong += f.id == (i & 0x3FFU) + 1U ? 0U : 1U;
  }
  echo.join();
  EXPECT_EQ(wrong, 0U);
  EXPECT_EQ(echoed.load(), kRounds);
}

}  // namespace
}  // namespace tread::hal
