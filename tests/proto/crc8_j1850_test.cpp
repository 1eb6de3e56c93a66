#include "proto/crc8_j1850.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace tread::proto {
namespace {

TEST(Crc8SaeJ1850, CatalogueCheckValue) {
  // CRC-8/SAE-J1850 (RevEng catalogue): check = 0x4B over the ASCII digits 1..9.
  const std::array<std::uint8_t, 9> digits{'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(crc8_sae_j1850(digits), 0x4BU);
}

struct Vector {
  std::vector<std::uint8_t> data;
  std::uint8_t crc;
};

TEST(Crc8SaeJ1850, AutosarCrcLibraryCheckValues) {
  // AUTOSAR SWS CRC Library, 8-bit SAE J1850 check values.
  const Vector vectors[] = {
      {{0x00, 0x00, 0x00, 0x00}, 0x59},
      {{0xF2, 0x01, 0x83}, 0x37},
      {{0x0F, 0xAA, 0x00, 0x55}, 0x79},
      {{0x00, 0xFF, 0x55, 0x11}, 0xB8},
      {{0x33, 0x22, 0x55, 0xAA, 0xBB, 0xCC, 0xDD, 0xEE, 0xFF}, 0xCB},
      {{0x92, 0x6B, 0x55}, 0x8C},
      {{0xFF, 0xFF, 0xFF, 0xFF}, 0x74},
  };
  for (const auto& v : vectors) {
    EXPECT_EQ(crc8_sae_j1850(v.data), v.crc);
  }
}

TEST(Crc8SaeJ1850, ChainingEqualsOneShot) {
  const std::array<std::uint8_t, 9> all{0x33, 0x22, 0x55, 0xAA, 0xBB, 0xCC, 0xDD, 0xEE, 0xFF};
  const std::uint8_t head = crc8_sae_j1850(std::span(all).first(4));
  EXPECT_EQ(crc8_sae_j1850(std::span(all).subspan(4), head), 0xCBU);
}

// The sliced implementation (8 and 4 bytes per step, then bytes) against a plain bitwise CRC, for
// every length up to two FD frames and every split point of a chained computation.
std::uint8_t bitwise_crc(const std::vector<std::uint8_t>& data) {
  std::uint8_t crc = 0xFFU;
  for (const std::uint8_t byte : data) {
    crc = static_cast<std::uint8_t>(crc ^ byte);
    for (int bit = 0; bit < 8; ++bit) {
      const bool msb = (crc & 0x80U) != 0U;
      crc = static_cast<std::uint8_t>(crc << 1U);
      if (msb) crc = static_cast<std::uint8_t>(crc ^ 0x1DU);
    }
  }
  return static_cast<std::uint8_t>(crc ^ 0xFFU);
}

TEST(Crc8SaeJ1850, SlicedEqualsBitwiseForEveryLengthAndSplit) {
  std::vector<std::uint8_t> all(130);
  std::uint32_t state = 12345U;
  for (auto& b : all) {
    state = state * 1664525U + 1013904223U;
    b = static_cast<std::uint8_t>(state >> 24U);
  }
  for (std::size_t len = 0; len <= all.size(); ++len) {
    const std::vector<std::uint8_t> data(all.begin(),
                                         all.begin() + static_cast<std::ptrdiff_t>(len));
    const std::uint8_t expected = bitwise_crc(data);
    ASSERT_EQ(crc8_sae_j1850(data), expected) << "length " << len;
    for (std::size_t split = 0; split <= len; split += 3U) {
      const std::uint8_t head = crc8_sae_j1850(std::span(data).first(split));
      ASSERT_EQ(crc8_sae_j1850(std::span(data).subspan(split), head), expected)
          << "length " << len << " split " << split;
    }
  }
}

TEST(Crc8SaeJ1850, EmptyInputGivesZero) {
  EXPECT_EQ(crc8_sae_j1850(std::span<const std::uint8_t>{}), 0x00U);
}

}  // namespace
}  // namespace tread::proto
