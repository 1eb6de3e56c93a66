#pragma once
// Kalker's creep coefficients of the linear theory of rolling contact for an elliptic contact
// area (Kalker 1967; table E.3 of Kalker, "Three-dimensional elastic bodies in rolling contact",
// 1990). With c = sqrt(a b) and G the combined shear modulus, the linear creep forces on the wheel
// are
//     Fx = -G c^2 C11 xi
//     Fy = -G c^2 C22 eta - G c^3 C23 phi
//     Mz =  G c^3 C23 eta - G c^4 C33 phi
// (xi, eta: longitudinal and lateral creepage; phi: spin creepage in 1/length).
//
// The table gives C11, C22, C23, C33 at a/b = 0.1 ... 1 and b/a = 0.1 ... 1 in steps of 0.1, each
// for Poisson's ratio 0, 0.25 and 0.5 (a: semi-axis in the rolling direction, b: lateral).
// Between table rows, with g = min(a/b, b/a), C g^p is interpolated linearly in g, the power p
// following how each coefficient grows toward slender ellipses (C23 ~ sqrt(g) and C33 ~ 1/g for
// a/b < 1; C11, C22 ~ 1/g and C23 ~ g^-1.5 for b/a < 1; p = 0 for the level ones): leaving each
// inner row out and interpolating it from its neighbours 0.2 apart, this misses by at most 1.7 %
// where plain linear interpolation (CONTACT's scheme) misses by up to 46 % (C23, b/a = 0.2).
// Between the three Poisson ratios: the parabola through 1/C (CONTACT's scheme, which reproduces
// its printed flexibilities exactly). Beyond g = 0.1 the row at 0.1 is carried along
// Kalker's asymptotic forms for slender ellipses (ratio to the asymptote held at g = 0.1), so the
// coefficients stay continuous and grow as the theory says; C33 on the b/a side (no usable
// asymptote) is held at its g = 0.1 value. Such values are flagged `extrapolated`.
//
// Sources of the numbers: docs/contact-mechanics.md.

namespace tread::rail {

template <typename T>
struct KalkerCoefficients {
  T c11{};
  T c22{};
  T c23{};
  T c33{};
  bool extrapolated = false;  ///< a/b or b/a below 0.1, outside the published table
};

/// Coefficients at semi-axis ratio a_over_b (> 0; a along the rolling direction) and Poisson's
/// ratio nu in [0, 0.5]. Arguments outside are clamped (a_over_b to [1e-3, 1e3]); NaN gives the
/// circular contact at nu = 0.25, flagged extrapolated.
template <typename T>
KalkerCoefficients<T> kalker_coefficients(T a_over_b, T nu) noexcept;

/// The power p of the interpolation above for coefficient 0..3 (C11, C22, C23, C33).
double kalker_interpolation_power(bool a_over_b_block, int coefficient) noexcept;

/// One published table entry (no interpolation): row 0..9 is g = 0.1 ... 1.0, nu_column 0..2 is
/// nu = 0, 0.25, 0.5; a_over_b_block true for the a/b <= 1 block. For tests and documentation.
KalkerCoefficients<double> kalker_table_entry(bool a_over_b_block, int row, int nu_column) noexcept;

extern template KalkerCoefficients<float> kalker_coefficients<float>(float, float) noexcept;
extern template KalkerCoefficients<double> kalker_coefficients<double>(double, double) noexcept;

}  // namespace tread::rail
