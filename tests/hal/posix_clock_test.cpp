#include "posix/posix_clock.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tread::hal
