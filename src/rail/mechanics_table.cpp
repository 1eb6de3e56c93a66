#include "rail/mechanics_table.hpp"

#include "rail/table_position.hpp"

namespace tread::rail {
namespace {

ContactPointData<float> to_point(const MechanicsPointF32& p) noexcept {
  ContactPointData<float> out;
  out.present = p.present > 0.5F;
  if (!out.present) {
    return out;
  }
  out.r_mm = p.r_mm;
  out.gamma_rad = p.gamma_rad;
  out.vertical_gap_mm = p.gap_mm;
  out.shape = {p.a_unit_mm, p.b_unit_mm, p.approach_unit_mm, 0.0F};
  out.c.c11 = p.c11;
  out.c.c22 = p.c22;
  out.c.c23 = p.c23;
  out.c.c33 = p.c33;
  return out;
}

float lerp(float a, float b, float f) noexcept {
  return a + (b - a) * f;
}

MechanicsPointF32 blend(const MechanicsPointF32& a, const MechanicsPointF32& b, float f) noexcept {
  const bool has_a = a.present > 0.5F;
  const bool has_b = b.present > 0.5F;
  if (has_a != has_b) {
    return f < 0.5F ? a : b;
  }
  if (!has_a) {
    return a;
  }
  return {1.0F,
          lerp(a.r_mm, b.r_mm, f),
          lerp(a.gamma_rad, b.gamma_rad, f),
          lerp(a.gap_mm, b.gap_mm, f),
          lerp(a.a_unit_mm, b.a_unit_mm, f),
          lerp(a.b_unit_mm, b.b_unit_mm, f),
          lerp(a.approach_unit_mm, b.approach_unit_mm, f),
          lerp(a.c11, b.c11, f),
          lerp(a.c22, b.c22, f),
          lerp(a.c23, b.c23, f),
          lerp(a.c33, b.c33, f)};
}

}  // namespace

Result<WheelsetContactPoints> lookup(const MechanicsTableF32& t, float y_mm) noexcept {
  Result<WheelsetContactPoints> r;
  if (t.count < 2U || !(t.y_step_mm > 0.0F) || t.rows == nullptr) {
    r.status = Status::invalid_argument;
    return r;
  }
  const Position p = locate(t.y_first_mm, t.y_step_mm, t.count, y_mm);
  r.status = p.status;
  const MechanicsRowF32& a = t.rows[p.index];
  const MechanicsRowF32& b = t.rows[p.index + 1U];
  for (int w = 0; w < 2; ++w) {
    for (int k = 0; k < 2; ++k) {
      r.value.wheel[w][k] = to_point(blend(a.point[w][k], b.point[w][k], p.fraction));
    }
  }
  if (!r.value.wheel[0][0].present || !r.value.wheel[1][0].present) {
    r.status = Status::invalid_argument;
  }
  return r;
}

MechanicsPointF32 to_row_point(const ContactPointData<double>& p) noexcept {
  if (!p.present) {
    return MechanicsPointF32{};
  }
  return {1.0F,
          static_cast<float>(p.r_mm),
          static_cast<float>(p.gamma_rad),
          static_cast<float>(p.vertical_gap_mm),
          static_cast<float>(p.shape.a_unit_mm),
          static_cast<float>(p.shape.b_unit_mm),
          static_cast<float>(p.shape.approach_unit_mm),
          static_cast<float>(p.c.c11),
          static_cast<float>(p.c.c22),
          static_cast<float>(p.c.c23),
          static_cast<float>(p.c.c33)};
}

}  // namespace tread::rail
