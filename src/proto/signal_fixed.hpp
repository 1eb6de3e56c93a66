#pragma once
// The integer-only route between a signal's raw CAN integer and its physical value in fixed point
// (fixed::Fixed64, Q31.32), for cores without an FPU: physical = raw × factor + offset with the
// signal's factor and offset as Q31.32 constants (SignalSpec::factor_q32 / offset_q32, built with
// the constexpr tables), and back rounded to the nearest raw step (halves away from zero) and
// saturated like the float path (signal.hpp encode_signal). No float or double is touched.

#include <cstdint>
#include <span>

#include "core/status.hpp"
#include "fixed/fixed64.hpp"
#include "proto/signal.hpp"

namespace tread::proto {

/// Decodes a physical value: raw × factor + offset, exact in Q31.32 up to the constants' rounding
/// (half a step of 2^−32 each). A value outside the Q31.32 range decodes as invalid.
[[nodiscard]] inline fixed::Fixed64 decode_signal_fixed(
    const SignalSpec& spec, std::span<const std::uint8_t> data) noexcept {
  const std::int64_t raw = decode_raw_signal(spec, data);
  std::int64_t scaled = 0;
  std::int64_t value = 0;
  if (__builtin_mul_overflow(raw, spec.factor_q32, &scaled) ||
      __builtin_add_overflow(scaled, spec.offset_q32, &value) ||
      value == fixed::Fixed64::kInvalidRaw) {
    return fixed::Fixed64::invalid();
  }
  return fixed::Fixed64::from_raw(value);
}

/// Encodes a physical value: (value − offset) / factor rounded to the nearest raw step (halves
/// away from zero) and saturated to the raw range. An invalid value encodes as 0 (physical
/// `offset`), as a non-finite float does.
/// @retval Status::ok            encoded within half a step
/// @retval Status::out_of_range  saturated, or the value was invalid
inline Status encode_signal_fixed(const SignalSpec& spec, fixed::Fixed64 value,
                                  std::span<std::uint8_t> data) noexcept {
  if (!value.valid() || spec.factor_q32 <= 0) {
    static_cast<void>(encode_raw_signal(spec, 0, data));
    return Status::out_of_range;
  }
  // value − offset in Q31.32 may leave int64 only by less than 2^63: its sign then tells the side.
  std::int64_t diff = 0;
  const bool overflow = __builtin_sub_overflow(value.raw(), spec.offset_q32, &diff);
  const bool negative = overflow ? value.raw() < 0 : diff < 0;
  std::int64_t raw = 0;
  if (overflow) {
    raw = negative ? spec.raw_min() : spec.raw_max();
    static_cast<void>(encode_raw_signal(spec, raw, data));
    return Status::out_of_range;
  }
  // |diff| ≤ 2^63 and factor/2 < 2^62: the rounded quotient fits in uint64.
  const std::uint64_t magnitude = negative ? std::uint64_t{0} - static_cast<std::uint64_t>(diff)
                                           : static_cast<std::uint64_t>(diff);
  const auto factor = static_cast<std::uint64_t>(spec.factor_q32);
  const std::uint64_t steps = (magnitude + factor / 2U) / factor;
  const auto limit = static_cast<std::uint64_t>(negative ? -spec.raw_min() : spec.raw_max());
  if (steps > limit) {
    static_cast<void>(encode_raw_signal(spec, negative ? spec.raw_min() : spec.raw_max(), data));
    return Status::out_of_range;
  }
  raw = negative ? -static_cast<std::int64_t>(steps) : static_cast<std::int64_t>(steps);
  static_cast<void>(encode_raw_signal(spec, raw, data));
  return Status::ok;
}

}  // namespace tread::proto
