#include "posix/thread_can_link.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
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

TEST(ThreadCanLink, ABatchArrivesInOrderStampedAndWhatDoesNotFitIsRefusedAndCounted) {
  auto link = std::make_unique<ThreadCanLink>();
  ThreadCanEndpoint& a = link->endpoint(0);
  ThreadCanEndpoint& b = link->endpoint(1);
  PosixClock clock;
  std::array<proto::CanFrame, 13> burst{};
  for (std::size_t i = 0; i < burst.size(); ++i) {
    burst[i] = frame(0x300 + static_cast<std::uint32_t>(i), static_cast<std::uint8_t>(i));
  }
  const std::int64_t before = clock.now_ns();
  ASSERT_EQ(a.send_batch(burst), burst.size());
  const std::int64_t after = clock.now_ns();
  EXPECT_EQ(a.send_batch(std::span<const proto::CanFrame>()), 0U);
  proto::CanFrame f{};
  std::int64_t last = before;
  for (std::size_t i = 0; i < burst.size(); ++i) {
    ASSERT_EQ(b.receive(f), Status::ok);
    EXPECT_EQ(f.id, 0x300U + i);
    EXPECT_EQ(f.data[0], i);
    EXPECT_GE(f.timestamp_ns, last);  // each stamped as it was queued
    EXPECT_LE(f.timestamp_ns, after);
    last = f.timestamp_ns;
  }
  EXPECT_EQ(b.receive(f), Status::would_block);
  EXPECT_EQ(a.tx_dropped(), 0U);

  // Room for 5 more: the first 5 of the burst are queued, the other 8 refused and counted.
  for (std::size_t i = 0; i < kThreadLinkFrames - 5; ++i) {
    ASSERT_EQ(a.send(frame(1, 0)), Status::ok);
  }
  EXPECT_EQ(a.send_batch(burst), 5U);
  EXPECT_EQ(a.tx_dropped(), 8U);
  for (std::size_t i = 0; i < kThreadLinkFrames - 5; ++i) {
    ASSERT_EQ(b.receive(f), Status::ok);
  }
  for (std::size_t i = 0; i < 5; ++i) {
    ASSERT_EQ(b.receive(f), Status::ok);
    EXPECT_EQ(f.id, 0x300U + i);
  }
  EXPECT_EQ(b.receive(f), Status::would_block);
}

/// `rounds` of a 13-frame batch from end 0 to end 1, each round answered by one frame back. End 1
/// takes each frame as it comes and waits again until it has the whole batch (as the rig waits for
/// a cycle's answer); end 0 waits for the answer. Every wait has a deadline 60 s away, so a lost
/// wake-up shows as a hang. Returns how many frames end 1 got out of order.
std::uint32_t batches_and_answers(ThreadCanLink& link, std::uint32_t rounds) {
  constexpr std::size_t kBurst = 13;
  constexpr std::int64_t kFar = 60'000'000'000;
  PosixClock clock;
  std::uint32_t out_of_order = 0;
  std::thread receiver([&] {
    ThreadCanEndpoint& b = link.endpoint(1);
    proto::CanFrame f{};
    for (std::uint32_t r = 0; r < rounds; ++r) {
      for (std::size_t got = 0; got < kBurst;) {
        if (b.receive(f) == Status::ok) {
          out_of_order += f.id == got && f.data[0] == (r & 0xFFU) ? 0U : 1U;
          ++got;
        } else {
          ASSERT_EQ(b.wait_until_ns(clock.now_ns() + kFar), Status::ok);
        }
      }
      ASSERT_EQ(b.send(frame(0x7FF, 0)), Status::ok);  // the round is done
    }
  });
  ThreadCanEndpoint& a = link.endpoint(0);
  std::array<proto::CanFrame, kBurst> burst{};
  proto::CanFrame f{};
  for (std::uint32_t r = 0; r < rounds; ++r) {
    for (std::size_t i = 0; i < kBurst; ++i) {
      burst[i] = frame(static_cast<std::uint32_t>(i), static_cast<std::uint8_t>(r & 0xFFU));
    }
    EXPECT_EQ(a.send_batch(burst), kBurst);
    while (a.receive(f) != Status::ok) {
      EXPECT_EQ(a.wait_until_ns(clock.now_ns() + kFar), Status::ok);
    }
  }
  receiver.join();
  return out_of_order;
}

// A receiver that sleeps until woken is woken at most once per batch, and never misses one.
TEST(ThreadCanLink, ABatchWakesASleepingEndOnceAtMost) {
  auto link = std::make_unique<ThreadCanLink>();
  constexpr std::uint32_t kRounds = 2'000;
  EXPECT_EQ(batches_and_answers(*link, kRounds), 0U);
  EXPECT_LE(link->endpoint(0).wake_calls(), std::uint64_t{kRounds});
  EXPECT_EQ(link->endpoint(0).tx_dropped(), 0U);
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

// An end that polls (the demo's rig) is never woken: the other thread's sends make no wake-up
// call, and it still sees every frame in order, answering an end that sleeps until woken.
TEST(ThreadCanLink, AnEndThatPollsCostsTheSenderNoWakeUpAndMissesNoFrame) {
  auto link = std::make_unique<ThreadCanLink>();
  ThreadCanEndpoint& polling = link->endpoint(1);
  polling.set_poll_interval_ns(20'000);
  EXPECT_EQ(batches_and_answers(*link, 500), 0U);
  EXPECT_EQ(link->endpoint(0).wake_calls(), 0U);  // the polling end never asked to be woken
  EXPECT_GT(polling.wake_calls(), 0U);            // the sleeping end did
  EXPECT_EQ(link->endpoint(0).tx_dropped(), 0U);

  // With nothing queued it returns at its deadline, not before.
  PosixClock clock;
  const std::int64_t deadline = clock.now_ns() + 2'000'000;
  EXPECT_EQ(polling.wait_until_ns(deadline), Status::would_block);
  EXPECT_GE(clock.now_ns(), deadline);
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
