#include "posix/posix_clock.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <thread>

#include "hal_concepts.hpp"
#include "posix/realtime.hpp"

namespace tread::hal {
namespace {

static_assert(Clock<PosixClock>);

TEST(PosixClock, AbsoluteSleepNeverWakesEarly) {
  PosixClock clock;
  const std::int64_t start = clock.now_ns();
  for (int i = 1; i <= 5; ++i) {
    const std::int64_t deadline = start + i * 1'000'000;
    ASSERT_EQ(clock.sleep_until_ns(deadline), Status::ok);
    EXPECT_GE(clock.now_ns(), deadline);
  }
  // A deadline in the past returns at once.
  const std::int64_t before = clock.now_ns();
  ASSERT_EQ(clock.sleep_until_ns(before - 1'000'000), Status::ok);
  EXPECT_LT(clock.now_ns() - before, 50'000'000);
}

TEST(Realtime, RefusalsAreReportedNotFatal) {
  RealtimeRequest request;
  request.cpu = 4096;  // no such CPU
  const RealtimeReport report = apply_realtime(request);
  EXPECT_FALSE(report.ok);
  EXPECT_NE(report.messages.find("affinity CPU 4096: refused"), std::string::npos)
      << report.messages;
}

TEST(Realtime, NothingRequestedIsOk) {
  const RealtimeReport report = apply_realtime(RealtimeRequest{});
  EXPECT_TRUE(report.ok);
  EXPECT_TRUE(report.messages.empty());
}

// A log writer started from the pinned SCHED_FIFO loop inherits both; become_helper takes it off
// the loop's CPU and back to the default scheduler.
TEST(Realtime, HelperLeavesTheRealtimeCpuAndPriority) {
  cpu_set_t online;
  CPU_ZERO(&online);
  ASSERT_EQ(::sched_getaffinity(0, sizeof(online), &online), 0);
  int loop_cpu = -1;
  for (int c = 0; c < CPU_SETSIZE && loop_cpu < 0; ++c) {
    if (CPU_ISSET(static_cast<std::size_t>(c), &online)) loop_cpu = c;
  }
  ASSERT_GE(loop_cpu, 0);
  const int usable = CPU_COUNT(&online);
  struct Seen {
    bool pinned{false}, fifo{false}, on_loop_cpu{true};
    int policy{-1}, cpus{0};
  } seen;
  std::thread helper([&] {
    // Pinned as the loop pins itself (apply_realtime keeps the CPUs it had before), then started
    // as a helper would be from there: on the loop's CPU at a SCHED_FIFO priority.
    RealtimeRequest pin;
    pin.cpu = loop_cpu;
    seen.pinned = apply_realtime(pin).ok;
    sched_param fifo{};
    fifo.sched_priority = 10;
    seen.fifo = ::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &fifo) == 0;  // root only
    become_helper(loop_cpu);
    sched_param param{};
    static_cast<void>(::pthread_getschedparam(::pthread_self(), &seen.policy, &param));
    cpu_set_t now;
    CPU_ZERO(&now);
    if (::pthread_getaffinity_np(::pthread_self(), sizeof(now), &now) == 0) {
      seen.on_loop_cpu = CPU_ISSET(static_cast<std::size_t>(loop_cpu), &now);
      seen.cpus = CPU_COUNT(&now);
    }
  });
  helper.join();
  ASSERT_TRUE(seen.pinned);
  EXPECT_EQ(seen.policy, SCHED_OTHER) << "SCHED_FIFO granted first: " << seen.fifo;
  if (usable >= 2) {
    EXPECT_FALSE(seen.on_loop_cpu);
    EXPECT_EQ(seen.cpus, usable - 1);
  } else {
    EXPECT_TRUE(seen.on_loop_cpu);  // the only CPU: left where it is
  }
}

}  // namespace
}  // namespace tread::hal
