#pragma once
// CRC8 SAE J1850 (polynomial 0x1D), the CRC of AUTOSAR E2E profile 1.

#include <cstddef>
#include <cstdint>
#include <span>

namespace tread::proto {

/// CRC8 SAE J1850 as AUTOSAR's Crc_CalculateCRC8: the register starts at `start ^ 0xFF` and the
/// result is XORed with 0xFF on exit. With the default `start = 0x00` this is the plain
/// CRC-8/SAE-J1850 (register init 0xFF, xorout 0xFF, check("123456789") = 0x4B). To continue a CRC
/// over several buffers, pass the previous result as `start` (AUTOSAR's chaining rule).
[[nodiscard]] std::uint8_t crc8_sae_j1850(std::span<const std::uint8_t> data,
                                          std::uint8_t start = 0x00U) noexcept;

}  // namespace tread::proto
