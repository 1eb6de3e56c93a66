#include "rail/contact_lookup.hpp"

#include <cmath>

#include "rail/table_position.hpp"

namespace tread::rail {
namespace {

inline float lerp(const float* column, const Position& p) noexcept {
  const float a = column[p.index];
  const float b = column[p.index + 1U];
  return a + (b - a) * p.fraction;
}

bool valid(std::uint32_t count, float step) noexcept {
  return count >= 2U && step > 0.0F;
}

struct PositionQ {
  std::uint32_t index;
  std::int32_t fraction_q16;  ///< 0..65536: the way to the next row, in 1/65536 of a step
  Status status;
};

PositionQ locate_q(std::int32_t y_first, std::int32_t y_step, std::uint32_t count,
                   std::int32_t y) noexcept {
  const std::int64_t span = static_cast<std::int64_t>(count - 1U) * y_step;
  std::int64_t offset = static_cast<std::int64_t>(y) - y_first;
  Status status = Status::ok;
  if (offset < 0) {
    offset = 0;
    status = Status::out_of_range;
  } else if (offset > span) {
    offset = span;
    status = Status::out_of_range;
  }
  // One 32-bit division for the row and one for the fraction (the table spans < 2^31 units).
  const auto off = static_cast<std::uint32_t>(offset);
  const auto step = static_cast<std::uint32_t>(y_step);
  std::uint32_t index = off / step;
  std::uint32_t rem = off - index * step;
  if (index >= count - 1U) {
    index = count - 2U;
    rem = step;
  }
  const auto fraction = static_cast<std::int32_t>((static_cast<std::uint64_t>(rem) << 16U) / step);
  return {index, fraction, status};
}

/// a + (b - a)·fraction, rounded to nearest (half up). The fraction's resolution is 1/65536 of a
/// step (0.0015 µm for a 0.1 mm step): far below the 0.1 µm unit.
std::int32_t lerp_q(std::int32_t a, std::int32_t b, const PositionQ& p) noexcept {
  const std::int64_t d = static_cast<std::int64_t>(b) - a;
  return static_cast<std::int32_t>(a + ((d * p.fraction_q16 + 32768) >> 16));
}

}  // namespace

Result<ContactSample> lookup(const ContactTableF32& t, float y_mm) noexcept {
  Result<ContactSample> r;
  if (!valid(t.count, t.y_step_mm) || t.rows == nullptr) {
    r.status = Status::invalid_argument;
    return r;
  }
  const Position p = locate(t.y_first_mm, t.y_step_mm, t.count, y_mm);
  r.status = p.status;
  const ContactRowF32& a = t.rows[p.index];
  const ContactRowF32& b = t.rows[p.index + 1U];
  const float f = p.fraction;
  r.value.r_left_mm = a.r_left_mm + (b.r_left_mm - a.r_left_mm) * f;
  r.value.r_right_mm = a.r_right_mm + (b.r_right_mm - a.r_right_mm) * f;
  r.value.delta_r_mm = a.delta_r_mm + (b.delta_r_mm - a.delta_r_mm) * f;
  r.value.gamma_left_rad = a.gamma_left_rad + (b.gamma_left_rad - a.gamma_left_rad) * f;
  r.value.gamma_right_rad = a.gamma_right_rad + (b.gamma_right_rad - a.gamma_right_rad) * f;
  return r;
}

Result<ContactSampleQ> lookup(const ContactTableQ& t, std::int32_t y) noexcept {
  Result<ContactSampleQ> r;
  if (t.count < 2U || t.y_step <= 0 || t.rows == nullptr) {
    r.status = Status::invalid_argument;
    return r;
  }
  const PositionQ p = locate_q(t.y_first, t.y_step, t.count, y);
  r.status = p.status;
  const ContactRowQ& a = t.rows[p.index];
  const ContactRowQ& b = t.rows[p.index + 1U];
  r.value.r_left = lerp_q(a.r_left, b.r_left, p);
  r.value.r_right = lerp_q(a.r_right, b.r_right, p);
  r.value.delta_r = lerp_q(a.delta_r, b.delta_r, p);
  r.value.gamma_left = lerp_q(a.gamma_left, b.gamma_left, p);
  r.value.gamma_right = lerp_q(a.gamma_right, b.gamma_right, p);
  return r;
}

Result<float> lookup(const RadiusTableF32& t, float y_mm) noexcept {
  Result<float> r;
  if (!valid(t.count, t.y_step_mm) || t.z_mm == nullptr) {
    r.status = Status::invalid_argument;
    return r;
  }
  const Position p = locate(t.y_first_mm, t.y_step_mm, t.count, y_mm);
  r.status = p.status;
  r.value = lerp(t.z_mm, p);
  return r;
}

Result<std::int32_t> lookup(const RadiusTableQ& t, std::int32_t y) noexcept {
  Result<std::int32_t> r;
  if (t.count < 2U || t.y_step <= 0 || t.z == nullptr) {
    r.status = Status::invalid_argument;
    return r;
  }
  const PositionQ p = locate_q(t.y_first, t.y_step, t.count, y);
  r.status = p.status;
  r.value = lerp_q(t.z[p.index], t.z[p.index + 1U], p);
  return r;
}

}  // namespace tread::rail
