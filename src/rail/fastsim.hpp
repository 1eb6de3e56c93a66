#pragma once
// Kalker's FASTSIM (Kalker, Vehicle System Dynamics 11, 1982): the simplified theory of rolling
// contact, in which the surface displacement at a point is its traction times a flexibility L,
// u = L p, with one flexibility per creepage chosen so that the linear theory comes out exactly:
//     L1 = 8 a / (3 G C11),  L2 = 8 a / (3 G C22),  L3 = pi a sqrt(a/b) / (4 G C23).
// The ellipse is cut into strips parallel to the rolling direction; along each, from the leading
// edge (x = +a_j, traction zero) to the trailing edge, the traction grows with the rigid slip
//     dp_x = -(xi / L1 - phi y / L3) dx,   dp_y = -(eta / L2 + phi x / L3) dx
// as long as it stays within the traction bound mu p_n(x, y); where it would exceed the bound it is
// scaled back onto it (slip). The bound is the parabolic pressure of the simplified theory,
// 2 N / (pi a b) (1 - x^2/a^2 - y^2/b^2) (Kalker's choice), or Hertz's elliptic pressure
// 3 N / (2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2).
//
// Each strip j has the same number of elements (nx) between its own ends; the traction is kept at
// element centres and advanced with the slip at the element boundary between them, which is exact
// for the linear slip field, so at small creepage the forces equal Kalker's linear theory up to
// the strip quadrature. Forces and moment on the wheel, conventions of creep_force.hpp.

#include "rail/creep_force.hpp"

namespace tread::rail {

enum class TractionBound : unsigned char { parabolic, elliptic };

struct FastsimGrid {
  int nx = 40;  ///< elements per strip, 1 ... 400
  int ny = 40;  ///< strips, 1 ... 400
  TractionBound bound = TractionBound::parabolic;
};

template <typename T>
struct FastsimResult {
  CreepForce<T> force{};
  T adhesion_fraction{};  ///< share of the contact area in adhesion (0 ... 1)
};

/// Creep force on the wheel at friction coefficient mu. A grid outside its limits is clamped to
/// them; normal force <= 0 gives zero.
template <typename T>
FastsimResult<T> fastsim(const CreepContact<T>& contact, const Creepage<T>& creepage, T mu,
                         const FastsimGrid& grid = {}) noexcept;

extern template FastsimResult<float> fastsim<float>(const CreepContact<float>&,
                                                    const Creepage<float>&, float,
                                                    const FastsimGrid&) noexcept;
extern template FastsimResult<double> fastsim<double>(const CreepContact<double>&,
                                                      const Creepage<double>&, double,
                                                      const FastsimGrid&) noexcept;

}  // namespace tread::rail
