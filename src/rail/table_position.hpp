#pragma once
// Where a value falls on a uniform grid of `count` rows at y_first + i y_step: the row below and
// the fraction toward the next, clamped to the grid and reported (the float lookup tables share
// it).

#include <cmath>
#include <cstdint>

#include "core/status.hpp"

namespace tread::rail {

struct Position {
  std::uint32_t index;  ///< row below y (0 .. count - 2)
  float fraction;       ///< 0..1 toward the next row
  Status status;        ///< ok, or out_of_range when y lay outside (or was not finite)
};

/// count >= 2 and y_step > 0 (checked by the caller).
inline Position locate(float y_first, float y_step, std::uint32_t count, float y) noexcept {
  if (!std::isfinite(y)) {
    return {0, 0.0F, Status::out_of_range};
  }
  const float u = (y - y_first) / y_step;
  const auto last = static_cast<float>(count - 1U);
  if (u <= 0.0F) {
    return {0, 0.0F, u < 0.0F ? Status::out_of_range : Status::ok};
  }
  if (u >= last) {
    return {count - 2U, 1.0F, u > last ? Status::out_of_range : Status::ok};
  }
  const auto i = static_cast<std::uint32_t>(u);
  const std::uint32_t index = i < count - 1U ? i : count - 2U;
  return {index, u - static_cast<float>(index), Status::ok};
}

}  // namespace tread::rail
