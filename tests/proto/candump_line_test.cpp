// The core's heap-free candump line codec (the host's file-level reader is tested in
// tests/sim/candump_log_test.cpp).
#include "proto/candump_line.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tread::proto {
namespace {

TEST(CandumpLine, RoundTripsAndKeepsTheInterfaceAsAView) {
  const std::string text = "(1700000000.123456) vcan0 0A0##1000000000000000000000000";
  CandumpLine parsed;
  ASSERT_EQ(parse_candump_line(text, parsed), CandumpError::none);
  EXPECT_EQ(parsed.time_ns, 1'700'000'000'123'456'000LL);
  EXPECT_EQ(parsed.interface, "vcan0");
  EXPECT_TRUE(parsed.frame.fd);
  EXPECT_TRUE(parsed.frame.bit_rate_switch);
  EXPECT_EQ(parsed.frame.len, 12U);
  EXPECT_EQ(parsed.frame.timestamp_ns, parsed.time_ns);
  char back[kCandumpLineMax];
  EXPECT_EQ(format_candump_line(parsed.frame, parsed.time_ns, parsed.interface, back), text.size());
  EXPECT_EQ(std::string(back), text);
}

TEST(CandumpLine, TheLongestLineFits) {
  CanFrame f;
  f.fd = true;
  f.extended = true;
  f.id = 0x1FFFFFFF;
  f.len = kFdMaxLen;
  char line[kCandumpLineMax];
  const std::string iface(40, 'x');  // cut at 32
  const std::size_t n = format_candump_line(f, 9'223'372'036'854'775'807LL, iface, line);
  EXPECT_LT(n, kCandumpLineMax);
  EXPECT_EQ(std::string(line).size(), n);
}

TEST(CandumpLine, TheLatestTimestampThatFitsInNanoseconds) {
  CandumpLine parsed;
  ASSERT_EQ(parse_candump_line("(9223372035.999999) vcan0 123#00", parsed), CandumpError::none);
  EXPECT_EQ(parsed.time_ns, 9'223'372'035'999'999'000LL);
}

TEST(CandumpLine, EachMalformedLineSaysWhy) {
  const std::pair<const char*, CandumpError> cases[] = {
      {"1.0 vcan0 123#00", CandumpError::not_a_frame},
      {"(1000000 vcan0 123#00", CandumpError::bad_timestamp},
      {"(1.0) vcan0 123#00", CandumpError::bad_micros},
      {"(1x.000000) vcan0 123#00", CandumpError::bad_micros},
      // Seconds whose nanoseconds overflow int64 (found by fuzzing), from the first one on.
      {"(40000000000000.000000) vcan0 123#00", CandumpError::bad_timestamp},
      {"(9223372036.000000) vcan0 123#00", CandumpError::bad_timestamp},
      {"(1.000000) vcan0", CandumpError::no_interface},
      {"(1.000000) vcan0 12#00", CandumpError::bad_id_length},
      {"(1.000000) vcan0 12G#00", CandumpError::id_not_hex},
      {"(1.000000) vcan0 123##", CandumpError::no_fd_flags},
      {"(1.000000) vcan0 123#0", CandumpError::odd_data},
      {"(1.000000) vcan0 123#000000000000000000", CandumpError::bad_data_length},
      {"(1.000000) vcan0 123##100000000000000000000", CandumpError::bad_data_length},
      {"(1.000000) vcan0 123#0G", CandumpError::data_not_hex},
  };
  for (const auto& [text, error] : cases) {
    CandumpLine parsed;
    EXPECT_EQ(parse_candump_line(text, parsed), error) << text;
    EXPECT_STRNE(describe(error), "ok");
  }
  CandumpLine parsed;
  ASSERT_EQ(parse_candump_line("(1.000000) vcan0 123#000000000000000000", parsed),
            CandumpError::bad_data_length);
  EXPECT_EQ(parsed.data_len, 9U);
}

}  // namespace
}  // namespace tread::proto
