// host::write_shortest (sim/io/shortest_number.hpp): the text reads back to the same double as the
// 17 significant digits ("%.17g") written before, and fits kShortestNumberMaxChars.
#include "io/shortest_number.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

namespace {

std::string shortest(double v) {
  char buffer[tread::host::kShortestNumberMaxChars];
  return std::string(buffer, tread::host::write_shortest(buffer, v));
}

std::uint64_t bits_of(const std::string& text) {
  return std::bit_cast<std::uint64_t>(std::strtod(text.c_str(), nullptr));
}

TEST(ShortestNumber, ReadsBackAsSeventeenDigitsDo) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> any;
  std::uniform_real_distribution<double> plain(-1e5, 1e5);
  char g17[40];
  for (int i = 0; i < 200000; ++i) {
    const double v = i % 2 == 0 ? std::bit_cast<double>(any(rng)) : plain(rng);
    if (!std::isfinite(v)) continue;
    std::snprintf(g17, sizeof g17, "%.17g", v);
    const std::string s = shortest(v);
    ASSERT_EQ(bits_of(s), std::bit_cast<std::uint64_t>(v)) << s;
    ASSERT_EQ(bits_of(s), bits_of(g17)) << s << " vs " << g17;
    ASSERT_LE(s.size(), std::string(g17).size());
  }
}

TEST(ShortestNumber, ExtremesAndSpecialValues) {
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(4000.0), "4000");
  EXPECT_EQ(shortest(-0.0), "-0");
  EXPECT_EQ(shortest(1e300), "1e+300");
  EXPECT_EQ(shortest(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(shortest(-std::numeric_limits<double>::infinity()), "-inf");
  for (const double v :
       {-DBL_MIN, -DBL_MAX, -DBL_TRUE_MIN, -2.2250738585072009e-308, -1.2345678901234567e-300}) {
    EXPECT_LE(shortest(v).size(), tread::host::kShortestNumberMaxChars) << shortest(v);
    EXPECT_EQ(bits_of(shortest(v)), std::bit_cast<std::uint64_t>(v));
  }
}

}  // namespace
