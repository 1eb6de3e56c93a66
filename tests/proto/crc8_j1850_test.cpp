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

TEST(Crc8SaeJ1850, EmptyInputGivesZero) {
  EXPECT_EQ(crc8_sae_j1850(std::span<const std::uint8_t>{}), 0x00U);
}

}  // namespace
}  // namespace tread::proto
