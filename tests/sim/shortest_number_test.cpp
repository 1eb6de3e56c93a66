// host::write_shortest (sim/io/shortest_number.hpp): the text reads back to the same double as the
// 17 significant digits ("%.17g") written before, fits kShortestNumberMaxChars, is std::to_chars's
// character for character, and nothing is written past kShortestNumberRoom.
#include "io/shortest_number.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

namespace {

std::string shortest(double v) {
  char buffer[tread::host::kShortestNumberRoom];
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

// Compares write_shortest with std::to_chars on `v` and `-v`; counts the values that differ and
// reports the first few. Also checks that no byte past kShortestNumberRoom is touched.
class ToCharsComparison {
 public:
  void check(double v) {
    check_one(v);
    check_one(-v);
  }
  int differing() const { return differing_; }
  long compared() const { return compared_; }

 private:
  void check_one(double v) {
    constexpr std::size_t kRoom = tread::host::kShortestNumberRoom;
    std::array<char, kRoom + 64> ours{};
    ours.fill('#');
    char* end = tread::host::write_shortest(ours.data(), v);
    char theirs[64];
    const std::to_chars_result r = std::to_chars(theirs, theirs + sizeof theirs, v);
    ++compared_;
    const std::string a(ours.data(), end);
    const std::string b(theirs, r.ptr);
    bool untouched = true;
    for (std::size_t i = kRoom; i < ours.size(); ++i) untouched = untouched && ours[i] == '#';
    if (a != b || !untouched) {
      if (differing_ < 5) {
        ADD_FAILURE() << "write_shortest " << a << " vs std::to_chars " << b
                      << (untouched ? "" : " (wrote past kShortestNumberRoom)");
      }
      ++differing_;
    }
  }
  int differing_ = 0;
  long compared_ = 0;
};

TEST(ShortestNumber, SameTextAsToChars) {
  ToCharsComparison c;
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<std::uint64_t> any;
  // Every bit pattern is as likely: all exponents, subnormals, NaN payloads, infinities.
  for (int i = 0; i < 300000; ++i) c.check(std::bit_cast<double>(any(rng)));
  // Short decimals at every scale ("3220.83", "1e-05", "123456789012345e7"): the fixed /
  // scientific choice and its ties, integers with trailing zeros, 1 to 17 digits.
  std::uniform_int_distribution<int> digits(1, 17);
  std::uniform_int_distribution<int> scale(-330, 310);
  char text[64];
  for (int i = 0; i < 300000; ++i) {
    const int n = digits(rng);
    const std::uint64_t limit = static_cast<std::uint64_t>(std::pow(10.0, n));
    std::snprintf(text, sizeof text, "%llue%d", static_cast<unsigned long long>(any(rng) % limit),
                  scale(rng));
    c.check(std::strtod(text, nullptr));
  }
  // A few ulps either side of every power of ten and of 2^53, where digit counts and the
  // notation change.
  for (int k = -325; k <= 308; ++k) {
    const double p = std::pow(10.0, k);
    double down = p;
    double up = p;
    for (int j = 0; j < 4; ++j) {
      c.check(down);
      c.check(up);
      down = std::nextafter(down, 0.0);
      up = std::nextafter(up, INFINITY);
    }
  }
  double v53 = std::ldexp(1.0, 53);
  for (int j = 0; j < 8; ++j) {
    c.check(std::nextafter(v53, 0.0));
    c.check(v53);
    v53 = std::nextafter(v53, INFINITY);
  }
  for (const double v : {0.0, 1.0, 0.1, 0.0001, 0.00001, 1e15, 1e16, 123456789012345.0,
                         1234567890123456.0, 9007199254740991.0, 4000.0, DBL_MIN, DBL_MAX,
                         DBL_TRUE_MIN, static_cast<double>(INFINITY)}) {
    c.check(v);
  }
  EXPECT_EQ(c.differing(), 0) << "of " << c.compared();
}

}  // namespace
