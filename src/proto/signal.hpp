#pragma once
// One CAN signal: Intel (little-endian, DBC "@1") bit layout, scaling and limits, as a DBC defines
// it.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/signal_role.hpp"

namespace tread::proto {

struct SignalSpec {
  Role role;
  const char* name;         ///< DBC signal name (without the instance suffix)
  std::int8_t instance;     ///< wheel / wheelset index appended as "_<n>", or -1 for none
  std::uint16_t start_bit;  ///< Intel start bit (LSB position)
  std::uint8_t length;      ///< bits, 1..32
  bool is_signed;           ///< two's complement raw value
  double factor;  ///< physical = raw * factor + offset (exact decimal, as written in the DBC)
  double offset;
  const char* unit;
  float factor_f;  ///< factor and offset as float for the real-time path
  float offset_f;
  float inverse_factor_f;  ///< 1 / factor, so encoding multiplies
  // Derived once, at compile time, for the per-frame path (12 bytes a signal, and 16 for the
  // Q31.32 pair: the tables may live in RAM on a microcontroller):
  float raw_min_f;  ///< raw_min() as float (exact: |raw_min| ≤ 2^31)
  float raw_max_f;  ///< raw_max() as float (may round up for 32-bit signals)
  /// factor and offset in Q31.32 (fixed::Fixed64 raw values, rounded to nearest) for the
  /// integer-only path (signal_fixed.hpp); factor_q32 ≥ 1 for every DBC factor ≥ 2^−32.
  std::int64_t factor_q32;
  std::int64_t offset_q32;
  bool whole_bytes;         ///< starts on a byte and spans whole bytes
  std::uint8_t first_byte;  ///< start_bit / 8
  std::uint8_t byte_count;  ///< length / 8 when whole_bytes

  constexpr SignalSpec() : SignalSpec(Role::crc, "", -1, 0, 8, false, 1.0, 0.0, "") {}
  constexpr SignalSpec(Role role_, const char* name_, std::int8_t instance_, std::uint16_t start,
                       std::uint8_t len, bool signed_, double factor_, double offset_,
                       const char* unit_)
      : role(role_),
        name(name_),
        instance(instance_),
        start_bit(start),
        length(len),
        is_signed(signed_),
        factor(factor_),
        offset(offset_),
        unit(unit_),
        factor_f(static_cast<float>(factor_)),
        offset_f(static_cast<float>(offset_)),
        inverse_factor_f(static_cast<float>(1.0 / factor_)),
        raw_min_f(static_cast<float>(raw_min())),
        raw_max_f(static_cast<float>(raw_max())),
        factor_q32(to_q32(factor_)),
        offset_q32(to_q32(offset_)),
        whole_bytes((start % 8U) == 0U && (len % 8U) == 0U),
        first_byte(static_cast<std::uint8_t>(start / 8U)),
        byte_count(static_cast<std::uint8_t>(len / 8U)) {}

  [[nodiscard]] constexpr std::int64_t raw_min() const noexcept {
    return is_signed ? -(std::int64_t{1} << (length - 1U)) : 0;
  }
  [[nodiscard]] constexpr std::int64_t raw_max() const noexcept {
    return is_signed ? (std::int64_t{1} << (length - 1U)) - 1 : (std::int64_t{1} << length) - 1;
  }
  /// A DBC factor or offset in Q31.32, rounded half away from zero (evaluated where the tables
  /// are built: at compile time for the node's constexpr tables).
  static constexpr std::int64_t to_q32(double value) noexcept {
    const double scaled = value * 4294967296.0;
    return static_cast<std::int64_t>(scaled < 0.0 ? scaled - 0.5 : scaled + 0.5);
  }

  [[nodiscard]] constexpr double physical_min() const noexcept {
    return static_cast<double>(raw_min()) * factor + offset;
  }
  [[nodiscard]] constexpr double physical_max() const noexcept {
    return static_cast<double>(raw_max()) * factor + offset;
  }
};

/// Bits not on whole bytes (the out-of-line part of put_raw / get_raw).
void put_raw_bits(std::span<std::uint8_t> data, std::uint16_t start_bit, std::uint8_t length,
                  std::uint64_t raw) noexcept;
[[nodiscard]] std::uint64_t get_raw_bits(std::span<const std::uint8_t> data,
                                         std::uint16_t start_bit, std::uint8_t length) noexcept;

// The per-signal functions below are inline: the codec calls them for every signal of every frame
// (about 90 per node cycle), and a whole-byte signal then costs a handful of instructions.

/// Writes `raw` (its low `length` bits) at `start_bit`, Intel order. The caller checked the bounds.
inline void put_raw(std::span<std::uint8_t> data, std::uint16_t start_bit, std::uint8_t length,
                    std::uint64_t raw) noexcept {
  if ((start_bit % 8U) == 0U && (length % 8U) == 0U) {  // whole bytes: the common case
    for (std::size_t i = start_bit / 8U, n = length / 8U; n > 0U; --n, ++i) {
      data[i] = static_cast<std::uint8_t>(raw & 0xFFU);
      raw >>= 8U;
    }
    return;
  }
  put_raw_bits(data, start_bit, length, raw);
}

/// Reads `length` bits at `start_bit`, Intel order, zero-extended.
[[nodiscard]] inline std::uint64_t get_raw(std::span<const std::uint8_t> data,
                                           std::uint16_t start_bit, std::uint8_t length) noexcept {
  if ((start_bit % 8U) == 0U && (length % 8U) == 0U) {  // whole bytes: the common case
    std::uint64_t raw = 0;
    for (std::size_t i = (start_bit + length) / 8U; i-- > start_bit / 8U;) {
      raw = (raw << 8U) | data[i];
    }
    return raw;
  }
  return get_raw_bits(data, start_bit, length);
}

/// Integer signals (counters, masks, flags): the raw value saturated to the signal's range.
/// @retval Status::out_of_range  saturated
inline Status encode_raw_signal(const SignalSpec& spec, std::int64_t raw,
                                std::span<std::uint8_t> data) noexcept {
  Status status = Status::ok;
  if (raw < spec.raw_min()) {
    raw = spec.raw_min();
    status = Status::out_of_range;
  } else if (raw > spec.raw_max()) {
    raw = spec.raw_max();
    status = Status::out_of_range;
  }
  auto bits = static_cast<std::uint64_t>(raw) & ((std::uint64_t{1} << spec.length) - 1U);
  if (spec.whole_bytes && spec.byte_count == 2U) {  // most signals: straight-line stores
    data[spec.first_byte] = static_cast<std::uint8_t>(bits & 0xFFU);
    data[spec.first_byte + 1U] = static_cast<std::uint8_t>((bits >> 8U) & 0xFFU);
  } else if (spec.whole_bytes) {
    for (std::size_t i = spec.first_byte, n = spec.byte_count; n > 0U; --n, ++i) {
      data[i] = static_cast<std::uint8_t>(bits & 0xFFU);
      bits >>= 8U;
    }
  } else {
    put_raw_bits(data, spec.start_bit, spec.length, bits);
  }
  return status;
}

/// The raw value, sign-extended for signed signals.
[[nodiscard]] inline std::int64_t decode_raw_signal(const SignalSpec& spec,
                                                    std::span<const std::uint8_t> data) noexcept {
  std::uint64_t bits = 0;
  if (spec.whole_bytes && spec.byte_count == 2U) {
    bits = (std::uint64_t{data[spec.first_byte + 1U]} << 8U) | data[spec.first_byte];
  } else if (spec.whole_bytes) {
    for (std::size_t i = spec.first_byte + spec.byte_count; i-- > spec.first_byte;) {
      bits = (bits << 8U) | data[i];
    }
  } else {
    bits = get_raw_bits(data, spec.start_bit, spec.length);
  }
  if (spec.is_signed && ((bits >> (spec.length - 1U)) & 1U) != 0U) {
    return static_cast<std::int64_t>(bits) - (std::int64_t{1} << spec.length);
  }
  return static_cast<std::int64_t>(bits);
}

/// Encodes a physical value: rounds to the nearest raw step (halves away from zero) and saturates
/// to the raw range. A non-finite value encodes as 0 (physical `offset`).
/// @retval Status::ok            encoded exactly within half a step
/// @retval Status::out_of_range  saturated, or the value was not finite
inline Status encode_signal(const SignalSpec& spec, float value,
                            std::span<std::uint8_t> data) noexcept {
  if (!std::isfinite(value)) {
    static_cast<void>(encode_raw_signal(spec, 0, data));
    return Status::out_of_range;
  }
  const float steps = (value - spec.offset_f) * spec.inverse_factor_f;
  // Compare in float before converting: the float may be far outside any integer range.
  if (steps < spec.raw_min_f) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_min(), data));
    return Status::out_of_range;
  }
  if (steps > spec.raw_max_f) {
    static_cast<void>(encode_raw_signal(spec, spec.raw_max(), data));
    return Status::out_of_range;
  }
  // Round half away from zero (no libm call on the hot path). float(raw_max) may round up past
  // raw_max for long signals; encode_raw_signal saturates exactly. Signals of up to 30 bits
  // (|steps| ≤ 2^30 + 0.5) convert through int32: the same integer, but one instruction on a
  // 32-bit core, where float → int64 is a soft-double library call (__aeabi_f2lz).
  std::int64_t raw = 0;
  if (spec.length <= 30U) {
    raw = steps >= 0.0F ? static_cast<std::int32_t>(steps + 0.5F)
                        : -static_cast<std::int32_t>(0.5F - steps);
  } else {
    raw = steps >= 0.0F ? static_cast<std::int64_t>(steps + 0.5F)
                        : -static_cast<std::int64_t>(0.5F - steps);
  }
  static_cast<void>(encode_raw_signal(spec, raw, data));
  return Status::ok;
}

/// Decodes a physical value.
[[nodiscard]] inline float decode_signal(const SignalSpec& spec,
                                         std::span<const std::uint8_t> data) noexcept {
  const std::int64_t raw = decode_raw_signal(spec, data);
  // Up to 31 bits through int32: the same rounding to float, without the int64 library call.
  const float value = spec.length <= 31U ? static_cast<float>(static_cast<std::int32_t>(raw))
                                         : static_cast<float>(raw);
  return value * spec.factor_f + spec.offset_f;
}

}  // namespace tread::proto
