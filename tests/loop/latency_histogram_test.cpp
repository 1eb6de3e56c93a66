// hal::LatencyHistogram: 1 µs buckets to 20 ms, an overflow bucket above; percentiles in µs, and
// the report's text of one in the overflow bucket (">= 20000": a p99 of 582 ms printed as 20000).
#include "loop/latency_histogram.hpp"

#include <gtest/gtest.h>

#include "runtime/node_session.hpp"

namespace {

using tread::hal::LatencyHistogram;

TEST(LatencyHistogram, PercentilesAndTheOverflowBucket) {
  LatencyHistogram h;
  EXPECT_EQ(h.percentile_us(0.5), 0);
  for (int i = 1; i <= 100; ++i) h.add_ns(i * 1000);  // 1 … 100 µs
  EXPECT_EQ(h.percentile_us(0.50), 50);
  EXPECT_EQ(h.percentile_us(0.99), 99);
  EXPECT_EQ(tread::host::percentile_text(h, 0.99), "99");
  EXPECT_EQ(h.max_ns(), 100'000);
  for (int i = 0; i < 200; ++i) h.add_ns(582'635'700);  // 582 ms: the overflow bucket
  EXPECT_EQ(h.percentile_us(0.99), LatencyHistogram::kOverflowUs);
  EXPECT_EQ(tread::host::percentile_text(h, 0.99), ">= 20000");
  EXPECT_EQ(h.max_ns(), 582'635'700);
  EXPECT_EQ(h.count(), 300u);
  h.add_ns(-5);  // a clock step back counts as 0
  EXPECT_EQ(h.count(), 301u);
}

}  // namespace
