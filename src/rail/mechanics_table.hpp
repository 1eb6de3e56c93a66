#pragma once
// The wheel-rail contact mechanics table of a wheelset: per lateral displacement y on a uniform
// grid, for each wheel its (up to two) contact points with everything that does not depend on the
// load (rail/wheel_contact.hpp's ContactPointData): rolling radius, contact angle, vertical gap,
// the Hertz shape at 1 N and Kalker's coefficients. Built by the host at init (or generated into
// flash), read by the node every cycle: O(1) index and linear interpolation, no heap.

#include <cstdint>

#include "rail/wheel_contact.hpp"

namespace tread::rail {

/// One contact point of one row (float, 11 values).
struct MechanicsPointF32 {
  float present;  ///< 1: the point exists, 0: none (the other fields are then 0)
  float r_mm;
  float gamma_rad;
  float gap_mm;
  float a_unit_mm;
  float b_unit_mm;
  float approach_unit_mm;
  float c11;
  float c22;
  float c23;
  float c33;
};

/// One row: [wheel: 0 left, 1 right][point: 0 main, 1 second].
struct MechanicsRowF32 {
  MechanicsPointF32 point[2][2];
};

struct MechanicsTableF32 {
  float y_first_mm{0.0F};
  float y_step_mm{0.0F};
  std::uint32_t count{0};
  const MechanicsRowF32* rows{nullptr};
};

/// The contact points of both wheels at y.
struct WheelsetContactPoints {
  ContactPointData<float> wheel[2][2];  ///< [left/right][main/second]
};

/// Between two rows every value is interpolated linearly; a second point that exists in only one
/// of them is taken from the nearer row.
/// @retval Status::ok               y inside the table
/// @retval Status::out_of_range     y outside (or not finite): the nearest end's values
/// @retval Status::invalid_argument the table is empty or malformed (points all absent)
Result<WheelsetContactPoints> lookup(const MechanicsTableF32& table, float y_mm) noexcept;

/// The row entry of a (double) contact point, for the builders of tables.
MechanicsPointF32 to_row_point(const ContactPointData<double>& p) noexcept;

}  // namespace tread::rail
