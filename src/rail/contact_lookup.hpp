#pragma once
// Wheel–rail contact lookup for the real-time core: tables over a uniform grid of wheelset lateral
// displacement y, O(1) index + linear interpolation, no heap. Tables live in flash (generated into
// lut/ at build time) or in RAM (built by a host tool at init); this view does not own them.
//
// Two storage variants: float32, and fixed point (int32; radii and Δr in units of 0.1 µm, angles in
// µrad) for targets without an FPU. Out-of-range y is clamped to the table and reported.

#include <cstdint>

#include "core/status.hpp"

namespace tread::rail {

struct ContactSample {
  float r_left_mm{0.0F};
  float r_right_mm{0.0F};
  float delta_r_mm{0.0F};
  float gamma_left_rad{0.0F};
  float gamma_right_rad{0.0F};
};

/// One row of a float contact table (rows are stored together: a lookup reads one cache line).
struct ContactRowF32 {
  float r_left_mm;
  float r_right_mm;
  float delta_r_mm;
  float gamma_left_rad;
  float gamma_right_rad;
};

/// A float table with `count` ≥ 2 rows at y = y_first_mm + i·y_step_mm.
struct ContactTableF32 {
  float y_first_mm{0.0F};
  float y_step_mm{0.0F};
  std::uint32_t count{0};
  const ContactRowF32* rows{nullptr};
};

/// One row of a fixed-point contact table.
struct ContactRowQ {
  std::int32_t r_left;       ///< 0.1 µm
  std::int32_t r_right;      ///< 0.1 µm
  std::int32_t delta_r;      ///< 0.1 µm
  std::int32_t gamma_left;   ///< µrad
  std::int32_t gamma_right;  ///< µrad
};

/// Fixed-point table: y in µm (kQYPerMm units per mm), values as documented above.
struct ContactTableQ {
  std::int32_t y_first{0};  ///< first y, in y units
  std::int32_t y_step{0};   ///< step, in y units (> 0)
  std::uint32_t count{0};
  const ContactRowQ* rows{nullptr};
};

inline constexpr std::int32_t kQLengthPerMm = 10'000;  ///< 0.1 µm units per mm
inline constexpr std::int32_t kQAnglePerRad = 1'000'000;
inline constexpr std::int32_t kQYPerMm = 1'000;  ///< y units per mm (1 µm)

using ContactSampleQ = ContactRowQ;

/// @retval Status::ok               y inside the table
/// @retval Status::out_of_range     y outside (or not finite): the nearest end's values
/// @retval Status::invalid_argument the table is empty or malformed
Result<ContactSample> lookup(const ContactTableF32& table, float y_mm) noexcept;

/// Fixed point: `y` in the table's y units (µm); integer-only arithmetic.
Result<ContactSampleQ> lookup(const ContactTableQ& table, std::int32_t y) noexcept;

/// A wheel profile's rolling radius r(y) = r0 + z(y) over a uniform grid (float).
struct RadiusTableF32 {
  float y_first_mm{0.0F};
  float y_step_mm{0.0F};
  std::uint32_t count{0};
  const float* z_mm{nullptr};
};

/// z(y) (radius increase); as lookup() above.
Result<float> lookup(const RadiusTableF32& table, float y_mm) noexcept;

/// Fixed point r(y) table: y in µm units (kQYPerMm), z in 0.1 µm (kQLengthPerMm).
struct RadiusTableQ {
  std::int32_t y_first{0};
  std::int32_t y_step{0};
  std::uint32_t count{0};
  const std::int32_t* z{nullptr};
};

/// z(y) in 0.1 µm for y in µm; integer-only.
Result<std::int32_t> lookup(const RadiusTableQ& table, std::int32_t y) noexcept;

}  // namespace tread::rail
