#include "proto/signal.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace tread::proto {
namespace {

TEST(SignalBits, IntelLayoutMatchesHandComputedBytes) {
  std::array<std::uint8_t, 8> data{};
  // 0x2710 (10000) at start bit 16, 16 bits, little-endian: bytes 2..3 = 10 27.
  put_raw(data, 16, 16, 0x2710U);
  EXPECT_EQ(data[2], 0x10U);
  EXPECT_EQ(data[3], 0x27U);
  // 4 bits at 12 (high nibble of byte 1) leave the low nibble alone.
  data[1] = 0x05U;
  put_raw(data, 12, 4, 0xAU);
  EXPECT_EQ(data[1], 0xA5U);
  // A field straddling bytes: 24 bits at 40.
  put_raw(data, 40, 24, 0xABCDEFU);
  EXPECT_EQ(data[5], 0xEFU);
  EXPECT_EQ(data[6], 0xCDU);
  EXPECT_EQ(data[7], 0xABU);
  EXPECT_EQ(get_raw(data, 40, 24), 0xABCDEFU);
  EXPECT_EQ(get_raw(data, 12, 4), 0xAU);
  EXPECT_EQ(get_raw(data, 8, 4), 0x5U);
}

TEST(SignalBits, OddPositionsRoundTrip) {
  for (std::uint16_t start = 0; start < 40; start += 3) {
    for (std::uint8_t len = 1; len <= 24; len += 5) {
      std::array<std::uint8_t, 8> data{};
      data.fill(0xFFU);
      const std::uint64_t value = 0x5A5A5AU & ((1ULL << len) - 1U);
      put_raw(data, start, len, value);
      EXPECT_EQ(get_raw(data, start, len), value) << start << ' ' << int{len};
      // Bits outside the field are untouched.
      if (start > 0) {
        EXPECT_EQ(get_raw(data, 0, static_cast<std::uint8_t>(start > 24 ? 24 : start)),
                  (1ULL << (start > 24 ? 24 : start)) - 1U);
      }
    }
  }
}

constexpr SignalSpec kKappa{Role::kappa, "Kappa", -1, 16, 16, true, 5e-5, 0.0, ""};
constexpr SignalSpec kFz{Role::fz, "Fz", -1, 16, 16, false, 1.0, 0.0, "N"};

TEST(Signal, ScaledRoundTripWithinHalfAStep) {
  std::array<std::uint8_t, 8> data{};
  for (float v = -1.6F; v <= 1.6F; v += 0.0137F) {
    ASSERT_EQ(encode_signal(kKappa, v, data), Status::ok);
    EXPECT_NEAR(decode_signal(kKappa, data), v, 2.5e-5F + 1e-6F);
  }
}

TEST(Signal, NegativeValuesAreTwosComplement) {
  std::array<std::uint8_t, 8> data{};
  ASSERT_EQ(encode_signal(kKappa, -0.5F, data), Status::ok);  // raw -10000 = 0xD8F0
  EXPECT_EQ(data[2], 0xF0U);
  EXPECT_EQ(data[3], 0xD8U);
  EXPECT_EQ(decode_raw_signal(kKappa, data), -10000);
}

TEST(Signal, SaturatesAndReportsOutOfRange) {
  std::array<std::uint8_t, 8> data{};
  EXPECT_EQ(encode_signal(kKappa, 5.0F, data), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kKappa, data), 32767);
  EXPECT_EQ(encode_signal(kKappa, -5.0F, data), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kKappa, data), -32768);
  EXPECT_EQ(encode_signal(kFz, -3.0F, data), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kFz, data), 0);
  EXPECT_EQ(encode_signal(kFz, 1e30F, data), Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kFz, data), 65535);
}

TEST(Signal, NonFiniteEncodesAsZeroAndIsFlagged) {
  std::array<std::uint8_t, 8> data{};
  data.fill(0xFFU);
  EXPECT_EQ(encode_signal(kKappa, std::numeric_limits<float>::quiet_NaN(), data),
            Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kKappa, data), 0);
  EXPECT_EQ(encode_signal(kKappa, std::numeric_limits<float>::infinity(), data),
            Status::out_of_range);
  EXPECT_EQ(decode_raw_signal(kKappa, data), 0);
}

TEST(Signal, RangeFromSpec) {
  EXPECT_EQ(kKappa.raw_min(), -32768);
  EXPECT_EQ(kKappa.raw_max(), 32767);
  EXPECT_DOUBLE_EQ(kKappa.physical_max(), 32767 * 5e-5);
  EXPECT_EQ(kFz.raw_max(), 65535);
}

}  // namespace
}  // namespace tread::proto
