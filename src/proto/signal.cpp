#include "proto/signal.hpp"

namespace tread::proto {

// Intel layout: the signal's bits are bits [start, start+length) of the little-endian byte string.
// A signal of up to 32 bits spans at most 5 bytes: work on that window as one integer.
void put_raw_bits(std::span<std::uint8_t> data, std::uint16_t start_bit, std::uint8_t length,
                  std::uint64_t raw) noexcept {
  const std::size_t first = start_bit / 8U;
  const std::size_t last = (static_cast<std::size_t>(start_bit) + length - 1U) / 8U;
  const unsigned shift = start_bit % 8U;
  std::uint64_t window = 0;
  for (std::size_t i = last + 1U; i-- > first;) {
    window = (window << 8U) | data[i];
  }
  const std::uint64_t mask =
      ((length >= 64U) ? ~std::uint64_t{0} : ((std::uint64_t{1} << length) - 1U)) << shift;
  window = (window & ~mask) | ((raw << shift) & mask);
  for (std::size_t i = first; i <= last; ++i) {
    data[i] = static_cast<std::uint8_t>(window & 0xFFU);
    window >>= 8U;
  }
}

std::uint64_t get_raw_bits(std::span<const std::uint8_t> data, std::uint16_t start_bit,
                           std::uint8_t length) noexcept {
  const std::size_t first = start_bit / 8U;
  const std::size_t last = (static_cast<std::size_t>(start_bit) + length - 1U) / 8U;
  std::uint64_t window = 0;
  for (std::size_t i = last + 1U; i-- > first;) {
    window = (window << 8U) | data[i];
  }
  const std::uint64_t mask =
      (length >= 64U) ? ~std::uint64_t{0} : ((std::uint64_t{1} << length) - 1U);
  return (window >> (start_bit % 8U)) & mask;
}

}  // namespace tread::proto
