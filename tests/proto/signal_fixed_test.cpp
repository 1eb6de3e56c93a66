#include "proto/signal_fixed.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "proto/messages.hpp"

namespace tread::proto {
namespace {

using fixed::Fixed64;

// Raw values spread over a signal's range, its ends included.
std::array<std::int64_t, 7> sample_raws(const SignalSpec& s) {
  const std::int64_t lo = s.raw_min();
  const std::int64_t hi = s.raw_max();
  return {lo, lo + 1, lo / 2 + hi / 2, 0, 1, hi - 1, hi};
}

TEST(SignalFixed, EveryScaledSignalDecodesWithinTheConstantsRoundingAndRoundTripsExactly) {
  for (const Layout layout : {Layout::classic, Layout::fd}) {
    for (const MessageSpec& m : messages(layout)) {
      for (const SignalSpec& s : m.signals) {
        for (const std::int64_t raw : sample_raws(s)) {
          if (raw < s.raw_min() || raw > s.raw_max()) continue;
          std::array<std::uint8_t, 64> data{};
          ASSERT_EQ(encode_raw_signal(s, raw, data), Status::ok);
          const Fixed64 value = decode_signal_fixed(s, data);
          const double exact = static_cast<double>(raw) * s.factor + s.offset;
          if (exact >= 2147483648.0 || exact < -2147483648.0) {
            EXPECT_FALSE(value.valid()) << s.name << ' ' << raw;
            continue;
          }
          ASSERT_TRUE(value.valid()) << s.name << ' ' << raw;
          // Each Q31.32 constant within 2^−33: |raw| × 2^−33 + 2^−33.
          const double bound = (std::fabs(static_cast<double>(raw)) + 1.0) * 0x1p-33 + 1e-12;
          EXPECT_NEAR(value.to_double(), exact, bound) << s.name << ' ' << raw;
          std::array<std::uint8_t, 64> back{};
          EXPECT_EQ(encode_signal_fixed(s, value, back), Status::ok) << s.name << ' ' << raw;
          EXPECT_EQ(decode_raw_signal(s, back), raw) << m.name << '.' << s.name;
        }
      }
    }
  }
}

TEST(SignalFixed, EncodingRoundsHalvesAwayFromZeroAndSaturatesLikeTheFloatPath) {
  // 16-bit signed, factor 0.5, offset 0: exact in both paths.
  const SignalSpec s(Role::fx, "Fx", -1, 0, 16, true, 0.5, 0.0, "N");
  std::array<std::uint8_t, 8> a{};
  std::array<std::uint8_t, 8> b{};
  for (const double v : {0.25, -0.25, 0.75, -0.75, 1.0, -1.0, 0.2, -0.2, 16383.75, -16384.0,
                         16383.5, 16384.0, -16384.5, 1e6, -1e6}) {
    const Status fs = encode_signal_fixed(s, Fixed64::from_double(v), a);
    const Status ff = encode_signal(s, static_cast<float>(v), b);
    EXPECT_EQ(fs, ff) << v;
    EXPECT_EQ(decode_raw_signal(s, a), decode_raw_signal(s, b)) << v;
  }
  // An invalid value: 0, flagged, as a NaN.
  EXPECT_EQ(encode_signal_fixed(s, Fixed64::invalid(), a), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(s, a), 0);
  // Unsigned with an offset: below the offset saturates to 0.
  const SignalSpec u(Role::fz, "Fz", -1, 0, 16, false, 1.0, -100.0, "N");
  EXPECT_EQ(encode_signal_fixed(u, Fixed64(-101.0), a), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(u, a), 0);
  EXPECT_EQ(encode_signal_fixed(u, Fixed64(-99.5), a), Status::ok);
  EXPECT_EQ(decode_raw_signal(u, a), 1);
}

}  // namespace
}  // namespace tread::proto
