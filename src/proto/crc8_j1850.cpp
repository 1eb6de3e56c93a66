#include "proto/crc8_j1850.hpp"

#include <array>

namespace tread::proto {
namespace {

constexpr std::uint8_t kPolynomial = 0x1DU;

// Slicing by 8: kTables[0] is the usual byte table T (T[x] = CRC register after shifting the byte x
// through it); kTables[k][x] = T applied k + 1 times (x followed by k zero bytes). The CRC is
// linear over GF(2), so eight bytes b0..b7 advance the register r as
//   T⁸[r ^ b0] ^ T⁷[b1] ^ ... ^ T¹[b7]
// with eight independent lookups instead of a chain of eight dependent ones (2 KiB of tables).
using Table = std::array<std::uint8_t, 256>;

constexpr std::array<Table, 8> make_tables() noexcept {
  std::array<Table, 8> tables{};
  for (std::size_t i = 0; i < 256U; ++i) {
    auto crc = static_cast<std::uint8_t>(i);
    for (int bit = 0; bit < 8; ++bit) {
      const bool msb = (crc & 0x80U) != 0U;
      crc = static_cast<std::uint8_t>(crc << 1U);
      if (msb) {
        crc = static_cast<std::uint8_t>(crc ^ kPolynomial);
      }
    }
    tables[0][i] = crc;
  }
  for (std::size_t k = 1; k < tables.size(); ++k) {
    for (std::size_t i = 0; i < 256U; ++i) {
      tables[k][i] = tables[0][tables[k - 1U][i]];
    }
  }
  return tables;
}

constexpr std::array<Table, 8> kTables = make_tables();

}  // namespace

std::uint8_t crc8_sae_j1850(std::span<const std::uint8_t> data, std::uint8_t start) noexcept {
  auto crc = static_cast<std::uint8_t>(start ^ 0xFFU);
  const std::uint8_t* p = data.data();
  std::size_t n = data.size();
  for (; n >= 8U; n -= 8U, p += 8) {
    crc = static_cast<std::uint8_t>(kTables[7][static_cast<std::uint8_t>(crc ^ p[0])] ^
                                    kTables[6][p[1]] ^ kTables[5][p[2]] ^ kTables[4][p[3]] ^
                                    kTables[3][p[4]] ^ kTables[2][p[5]] ^ kTables[1][p[6]] ^
                                    kTables[0][p[7]]);
  }
  if (n >= 4U) {
    crc = static_cast<std::uint8_t>(kTables[3][static_cast<std::uint8_t>(crc ^ p[0])] ^
                                    kTables[2][p[1]] ^ kTables[1][p[2]] ^ kTables[0][p[3]]);
    n -= 4U;
    p += 4;
  }
  for (; n > 0U; --n, ++p) {
    crc = kTables[0][static_cast<std::uint8_t>(crc ^ *p)];
  }
  return static_cast<std::uint8_t>(crc ^ 0xFFU);
}

}  // namespace tread::proto
