#include "proto/signal.hpp"

#include <cmath>

namespace tread::proto {

// Intel layout: the signal's bits are bits [start, start+length) of the little-endian byte string.
// A signal of up to 32 bits spans at most 5 bytes: work on that window as one integer.
void put_raw(std::span<std::uint8_t> data, std::uint16_t start_bit, std::uint8_t length,
             std::uint64_t raw) noexcept {
  if ((start_bit % 8U) == 0U && (length % 8U) == 0U) {  // whole bytes: the common case
    for (std::size_t i = start_bit / 8U, n = length / 8U; n > 0U; --n, ++i) {
      data[i] = static_cast<std::uint8_t>(raw & 0xFFU);
      raw >>= 8U;
    }
    return;
  }
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

std::uint64_t get_raw(std::span<const std::uint8_t> data, std::uint16_t start_bit,
                      std::uint8_t length) noexcept {
  if ((start_bit % 8U) == 0U && (length % 8U) == 0U) {  // whole bytes: the common case
    std::uint64_t raw = 0;
    for (std::size_t i = (start_bit + length) / 8U; i-- > start_bit / 8U;) {
      raw = (raw << 8U) | data[i];
    }
    return raw;
  }
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

Status encode_raw_signal(const SignalSpec& spec, std::int64_t raw,
                         std::span<std::uint8_t> data) noexcept {
  Status status = Status::ok;
  if (raw < spec.raw_min()) {
    raw = spec.raw_min();
    status = Status::out_of_range;
  } else if (raw > spec.raw_max()) {
    raw = spec.raw_max();
    status = Status::out_of_range;
  }
  const std::uint64_t mask = (std::uint64_t{1} << spec.length) - 1U;
  put_raw(data, spec.start_bit, spec.length, static_cast<std::uint64_t>(raw) & mask);
  return status;
}

std::int64_t decode_raw_signal(const SignalSpec& spec,
                               std::span<const std::uint8_t> data) noexcept {
  const std::uint64_t bits = get_raw(data, spec.start_bit, spec.length);
  if (spec.is_signed && ((bits >> (spec.length - 1U)) & 1U) != 0U) {
    return static_cast<std::int64_t>(bits) - (std::int64_t{1} << spec.length);
  }
  return static_cast<std::int64_t>(bits);
}

Status encode_signal(const SignalSpec& spec, float value, std::span<std::uint8_t> data) noexcept {
  if (!std::isfinite(value)) {
    static_cast<void>(encode_raw_signal(spec, 0, data));
    return Status::out_of_range;
  }
  const float steps = (value - spec.offset_f) * spec.inverse_factor_f;
  // Compare in float before converting: the float may be far outside any integer range.
  if (steps < static_cast<float>(spec.raw_min())) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_min(), data));
    return Status::out_of_range;
  }
  if (steps > static_cast<float>(spec.raw_max())) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_max(), data));
    return Status::out_of_range;
  }
  // Round half away from zero (no libm call on the hot path). float(raw_max) may round up past
  // raw_max for long signals; encode_raw_signal saturates exactly.
  const auto raw = steps >= 0.0F ? static_cast<std::int64_t>(steps + 0.5F)
                                 : -static_cast<std::int64_t>(0.5F - steps);
  static_cast<void>(encode_raw_signal(spec, raw, data));
  return Status::ok;
}

float decode_signal(const SignalSpec& spec, std::span<const std::uint8_t> data) noexcept {
  return static_cast<float>(decode_raw_signal(spec, data)) * spec.factor_f + spec.offset_f;
}

}  // namespace tread::proto
