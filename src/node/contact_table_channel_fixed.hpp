#pragma once
// A rail-wheelset channel on the fixed-point contact table (rail::ContactTableQ: y in µm, radii
// and Δr in 0.1 µm, angles in µrad; integer interpolation), on Fixed64 inputs and results, for
// cores without an FPU: the lateral displacement is rounded to the table's µm (halves away from
// zero), the table's integers become Fixed64 mm and rad rounded to nearest. The semantics of
// ContactTableChannel: y outside the table is clamped and flagged; an empty or malformed table
// (or an invalid displacement) gives zeros, flagged as clamped.

#include <cstdint>

#include "core/status.hpp"
#include "fixed/fixed64.hpp"
#include "node/channels.hpp"
#include "proto/data_model.hpp"
#include "rail/contact_lookup.hpp"

namespace tread::node {

class ContactTableChannelFixed {
 public:
  using Scalar = fixed::Fixed64;

  ContactTableChannelFixed() = default;
  /// The table's rows must outlive the channel.
  explicit ContactTableChannelFixed(const rail::ContactTableQ& table) noexcept : table_(table) {}

  ContactResultFixed evaluate(const proto::WheelsetInputFixed& in) const noexcept {
    ContactResultFixed out;
    if (!in.lateral_mm.valid()) {
      out.clamped = true;
      return out;
    }
    const Result<rail::ContactSampleQ> r = rail::lookup(table_, to_table_y(in.lateral_mm));
    if (r.status == Status::invalid_argument) {
      out.clamped = true;
      return out;
    }
    out.r_left_mm = from_units(r.value.r_left, rail::kQLengthPerMm);
    out.r_right_mm = from_units(r.value.r_right, rail::kQLengthPerMm);
    out.delta_r_mm = from_units(r.value.delta_r, rail::kQLengthPerMm);
    out.gamma_left_rad = from_units(r.value.gamma_left, rail::kQAnglePerRad);
    out.gamma_right_rad = from_units(r.value.gamma_right, rail::kQAnglePerRad);
    out.clamped = r.status == Status::out_of_range;
    return out;
  }

  /// mm (Q31.32) → the table's y units (µm), rounded half away from zero, saturated to int32 (the
  /// lookup then clamps and flags).
  static std::int32_t to_table_y(fixed::Fixed64 lateral_mm) noexcept {
    const std::int64_t raw = lateral_mm.raw();
    const bool negative = raw < 0;
    // |raw| < 2^63 (valid); × 1000 may overflow: saturate first (|y| ≥ 2^31 µm is off any table).
    const std::uint64_t magnitude = negative ? std::uint64_t{0} - static_cast<std::uint64_t>(raw)
                                             : static_cast<std::uint64_t>(raw);
    constexpr std::uint64_t kLimit = std::uint64_t{1} << 53U;  // 2^21 mm: × 1000 < 2^63
    if (magnitude >= kLimit) {
      return negative ? INT32_MIN : INT32_MAX;
    }
    const std::uint64_t scaled = magnitude * static_cast<std::uint64_t>(rail::kQYPerMm);
    const std::uint64_t units = (scaled + (std::uint64_t{1} << 31U)) >> 32U;
    const std::uint64_t limit = negative ? std::uint64_t{1} << 31U : (std::uint64_t{1} << 31U) - 1U;
    const std::uint64_t clamped = units > limit ? limit : units;
    return negative ? static_cast<std::int32_t>(-static_cast<std::int64_t>(clamped))
                    : static_cast<std::int32_t>(clamped);
  }

  /// A table integer in 1/`per_unit` of a unit → Fixed64 units, rounded half away from zero.
  static fixed::Fixed64 from_units(std::int32_t value, std::int32_t per_unit) noexcept {
    // |value| · 2^32 < 2^63: exact in int64.
    const bool negative = value < 0;
    const std::uint64_t magnitude =
        (negative ? std::uint64_t{0} - static_cast<std::uint64_t>(std::int64_t{value})
                  : static_cast<std::uint64_t>(value))
        << 32U;
    const auto d = static_cast<std::uint64_t>(per_unit);
    const std::uint64_t q = (magnitude + d / 2U) / d;  // ≤ 2^63
    // The sign in unsigned arithmetic: −2^63 (INT32_MIN in whole units) has no positive twin.
    return fixed::Fixed64::from_raw(static_cast<std::int64_t>(negative ? std::uint64_t{0} - q : q));
  }

 private:
  rail::ContactTableQ table_{};
};

static_assert(ContactChannel<ContactTableChannelFixed>);

}  // namespace tread::node
