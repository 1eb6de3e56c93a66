#include "proto/crc8_j1850.hpp"

#include <array>

namespace tread::proto {
namespace {

constexpr std::uint8_t kPolynomial = 0x1DU;

constexpr std::array<std::uint8_t, 256> make_table() noexcept {
  std::array<std::uint8_t, 256> table{};
  for (std::size_t i = 0; i < table.size(); ++i) {
    auto crc = static_cast<std::uint8_t>(i);
    for (int bit = 0; bit < 8; ++bit) {
      const bool msb = (crc & 0x80U) != 0U;
      crc = static_cast<std::uint8_t>(crc << 1U);
      if (msb) {
        crc = static_cast<std::uint8_t>(crc ^ kPolynomial);
      }
    }
    table[i] = crc;
  }
  return table;
}

constexpr std::array<std::uint8_t, 256> kTable = make_table();

}  // namespace

std::uint8_t crc8_sae_j1850(std::span<const std::uint8_t> data, std::uint8_t start) noexcept {
  auto crc = static_cast<std::uint8_t>(start ^ 0xFFU);
  for (const std::uint8_t byte : data) {
    crc = kTable[static_cast<std::uint8_t>(crc ^ byte)];
  }
  return static_cast<std::uint8_t>(crc ^ 0xFFU);
}

}  // namespace tread::proto
