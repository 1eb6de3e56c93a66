#pragma once
// Hertz's solution for the normal contact of two bodies whose gap opens as A x^2 + B y^2 near the
// contact point (x: rolling direction, y: lateral; A, B the relative curvatures, e.g.
// A = (1/R_wheel + 1/R_rail,long) / 2). The contact area is an ellipse with semi-axes a (along x)
// and b (along y); with e the eccentricity (e^2 = 1 - (short/long)^2) and K(e), E(e) the complete
// elliptic integrals,
//     B/A (or A/B, >= 1)  = (E/(1 - e^2) - K) / (K - E),
//     long^3  = 3 P (K - E) / (2 pi E* e^2 min(A, B)),     short = long sqrt(1 - e^2),
//     approach = 3 P K / (2 pi E* long),   p_max = 3 P / (2 pi a b) = 1.5 p_mean,
// the long axis along the smaller curvature (Hertz 1882; Johnson, Contact Mechanics, ch. 4).
//
// The shape (e and the axes at unit load) depends only on A, B and E*: it is solved once on the
// host (double, AGM elliptic integrals, bracketed Illinois iteration on ln(b/a)) and stored per
// contact-table row; the loop only scales it by the load: axes with P^(1/3), approach with
// P^(2/3), pressures with P^(1/3).

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "core/status.hpp"

namespace tread::rail {

/// Complete elliptic integrals of the first and second kind, K(k) and E(k), from the complementary
/// modulus k' = sqrt(1 - k^2) in (0, 1] (accurate for slender ellipses where k -> 1). Also
/// (K - E) / k^2 without cancellation near k = 0. Arithmetic-geometric mean, double.
struct EllipticIntegrals {
  double k = 0.0;                ///< first kind
  double e = 0.0;                ///< second kind
  double k_minus_e_over_k2 = 0;  ///< (K - E) / k^2 (pi/4 at k = 0)
  double ratio = 1.0;            ///< (E/k'^2 - K) / (K - E): the curvature ratio of this ellipse
};
EllipticIntegrals elliptic_integrals(double k_complement) noexcept;

/// The load-independent part of a Hertz contact.
template <typename T>
struct HertzShape {
  T a_unit_mm{};         ///< semi-axis along x at a load of 1 N
  T b_unit_mm{};         ///< semi-axis along y at 1 N
  T approach_unit_mm{};  ///< mutual approach at 1 N
  T curvature_ratio{};   ///< B / A
};

/// Shape from the relative curvatures (1/mm, both > 0) and the contact modulus
/// E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) in MPa.
/// @retval Status::invalid_argument A or B not > 0 (conformal or non-Hertzian) or E* not > 0, or
///         not finite; the shape is then zero.
/// @retval Status::out_of_range     B/A or A/B above 1e8 (an ellipse thinner than the solver's
///         range): the shape at that limit ratio.
Result<HertzShape<double>> hertz_shape(double a_curv_per_mm, double b_curv_per_mm,
                                       double e_star_mpa) noexcept;

/// Cube root for the loop: float by a bit-level first guess (the exponent divided by three) and
/// two Halley steps (cubic convergence: ~3 % -> ~3e-5 -> exact to float rounding), about a third
/// of glibc's cbrtf; double by std::cbrt. x <= 0 or not finite gives 0.
template <typename T>
T cube_root(T x) noexcept {
  if (!(x > T{0}) || !(x < std::numeric_limits<T>::max())) {
    return T{0};
  }
  if constexpr (std::is_same_v<T, float>) {
    const auto bits = std::bit_cast<std::uint32_t>(x);
    float y = std::bit_cast<float>(bits / 3U + 709921077U);
    for (int i = 0; i < 2; ++i) {
      const float y3 = y * y * y;
      y *= (y3 + 2.0F * x) / (2.0F * y3 + x);
    }
    return y;
  } else {
    return std::cbrt(x);
  }
}

/// The contact under a load.
template <typename T>
struct HertzPatch {
  T a_mm{};
  T b_mm{};
  T approach_mm{};
  T p_max_mpa{};
  T p_mean_mpa{};
};

/// Scales a shape to the normal load (N). Loads <= 0 (or NaN) give an empty patch (all zero):
/// the wheel has lifted.
template <typename T>
HertzPatch<T> hertz_patch(const HertzShape<T>& shape, T load_n) noexcept;

/// The normal load that gives this approach (the inverse of hertz_patch's approach): 0 for
/// approach <= 0.
template <typename T>
T hertz_load_for_approach(const HertzShape<T>& shape, T approach_mm) noexcept;

/// Converts a double shape (host solve) to the loop's type.
template <typename T>
HertzShape<T> shape_as(const HertzShape<double>& s) noexcept {
  return {static_cast<T>(s.a_unit_mm), static_cast<T>(s.b_unit_mm),
          static_cast<T>(s.approach_unit_mm), static_cast<T>(s.curvature_ratio)};
}

/// E* of two bodies (MPa; Poisson ratios in [0, 0.5)).
inline double contact_modulus_mpa(double e1_mpa, double nu1, double e2_mpa, double nu2) noexcept {
  return 1.0 / ((1.0 - nu1 * nu1) / e1_mpa + (1.0 - nu2 * nu2) / e2_mpa);
}

extern template HertzPatch<float> hertz_patch<float>(const HertzShape<float>&, float) noexcept;
extern template HertzPatch<double> hertz_patch<double>(const HertzShape<double>&, double) noexcept;
extern template float hertz_load_for_approach<float>(const HertzShape<float>&, float) noexcept;
extern template double hertz_load_for_approach<double>(const HertzShape<double>&, double) noexcept;

}  // namespace tread::rail
