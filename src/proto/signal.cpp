#include "proto/signal.hpp"

#include <cmath>

namespace tread::proto {

void put_raw(std::span<std::uint8_t> data, std::uint16_t start_bit, std::uint8_t length,
             std::uint64_t raw) noexcept {
  for (std::uint32_t i = 0; i < length; ++i) {
    const std::uint32_t bit = start_bit + i;
    const std::size_t byte = bit / 8U;
    const auto mask = static_cast<std::uint8_t>(1U << (bit % 8U));
    if (((raw >> i) & 1U) != 0U) {
      data[byte] = static_cast<std::uint8_t>(data[byte] | mask);
    } else {
      data[byte] = static_cast<std::uint8_t>(data[byte] & static_cast<std::uint8_t>(~mask));
    }
  }
}

std::uint64_t get_raw(std::span<const std::uint8_t> data, std::uint16_t start_bit,
                      std::uint8_t length) noexcept {
  std::uint64_t raw = 0;
  for (std::uint32_t i = 0; i < length; ++i) {
    const std::uint32_t bit = start_bit + i;
    if (((static_cast<std::uint32_t>(data[bit / 8U]) >> (bit % 8U)) & 1U) != 0U) {
      raw |= std::uint64_t{1} << i;
    }
  }
  return raw;
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
  const float steps = std::nearbyint((value - spec.offset_f) / spec.factor_f);
  // Compare in float before converting: the float may be far outside any integer range.
  if (steps < static_cast<float>(spec.raw_min())) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_min(), data));
    return Status::out_of_range;
  }
  if (steps > static_cast<float>(spec.raw_max())) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_max(), data));
    return Status::out_of_range;
  }
  // float(raw_max) may round up past raw_max for long signals; encode_raw_signal saturates exactly.
  static_cast<void>(encode_raw_signal(spec, static_cast<std::int64_t>(steps), data));
  return Status::ok;
}

float decode_signal(const SignalSpec& spec, std::span<const std::uint8_t> data) noexcept {
  return static_cast<float>(decode_raw_signal(spec, data)) * spec.factor_f + spec.offset_f;
}

}  // namespace tread::proto
