#include "rail/hertz_ellipse.hpp"

#include <cmath>

namespace tread::rail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxRatio = 1e8;

double log_ratio_error(double s, double log_target) noexcept {
  return std::log(elliptic_integrals(std::exp(s)).ratio) - log_target;
}

/// ln(k') of the ellipse whose curvature ratio is `ratio` (> 1): bracketed Illinois iteration
/// (the function is monotone decreasing in s = ln k', and nearly linear: ratio ~ k'^(-3/2)).
double solve_log_k_complement(double ratio) noexcept {
  const double target = std::log(ratio);
  double s_hi = 0.0;  // circle: error -target < 0
  double f_hi = -target;
  double s_lo = -2.0 / 3.0 * target;
  double f_lo = log_ratio_error(s_lo, target);
  if (f_lo < 0.0) {
    double step = 0.5;
    s_hi = s_lo;
    f_hi = f_lo;
    for (int i = 0; i < 60 && f_lo < 0.0; ++i) {
      s_lo -= step;
      step *= 2.0;
      f_lo = log_ratio_error(s_lo, target);
    }
  }
  int side = 0;
  double s = s_lo;
  for (int i = 0; i < 100 && s_hi - s_lo > 1e-15; ++i) {
    s = (s_lo * f_hi - s_hi * f_lo) / (f_hi - f_lo);
    if (!(s > s_lo && s < s_hi)) {
      s = 0.5 * (s_lo + s_hi);
    }
    const double f = log_ratio_error(s, target);
    if (f > 0.0) {
      s_lo = s;
      f_lo = f;
      if (side == 1) {
        f_hi *= 0.5;
      }
      side = 1;
    } else {
      s_hi = s;
      f_hi = f;
      if (side == -1) {
        f_lo *= 0.5;
      }
      side = -1;
    }
    if (std::abs(f) < 1e-15) {
      return s;
    }
  }
  return s;
}

}  // namespace

EllipticIntegrals elliptic_integrals(double k_complement) noexcept {
  EllipticIntegrals out;
  const double kp = k_complement;
  const double k2 = (1.0 - kp) * (1.0 + kp);
  // AGM: a0 = 1, b0 = k', c0 = k; K = pi / (2 a_inf), E = K (1 - sum_n 2^(n-1) c_n^2).
  // q = sum_{n>=1} 2^(n-1) c_n^2 / k^2 with c1^2 / k^2 = (1 - k') / (4 (1 + k')) exactly.
  double a = 1.0;
  double b = kp;
  double q = 0.0;
  double weight = 1.0;  // 2^(n-1) for n = 1
  for (int n = 1; n < 40; ++n) {
    const double c = 0.5 * (a - b);
    if (n == 1) {
      q += (1.0 - kp) / (4.0 * (1.0 + kp));
    } else if (k2 > 0.0) {
      q += weight * c * c / k2;
    }
    const double next_b = std::sqrt(a * b);
    a = 0.5 * (a + b);
    b = next_b;
    weight *= 2.0;
    if (std::abs(c) <= 1e-17 * a) {
      break;
    }
  }
  out.k = kPi / (2.0 * a);
  const double s_over_k2 = 0.5 + q;  // sum_{n>=0} 2^(n-1) c_n^2 / k^2
  out.e = out.k * (1.0 - s_over_k2 * k2);
  out.k_minus_e_over_k2 = out.k * s_over_k2;
  out.ratio = (0.5 - q) / (kp * kp * (0.5 + q));
  return out;
}

Result<HertzShape<double>> hertz_shape(double a_curv_per_mm, double b_curv_per_mm,
                                       double e_star_mpa) noexcept {
  Result<HertzShape<double>> out;
  if (!(a_curv_per_mm > 0.0) || !(b_curv_per_mm > 0.0) || !(e_star_mpa > 0.0) ||
      !std::isfinite(a_curv_per_mm) || !std::isfinite(b_curv_per_mm) ||
      !std::isfinite(e_star_mpa)) {
    out.status = Status::invalid_argument;
    return out;
  }
  const double small = a_curv_per_mm < b_curv_per_mm ? a_curv_per_mm : b_curv_per_mm;
  const double large = a_curv_per_mm < b_curv_per_mm ? b_curv_per_mm : a_curv_per_mm;
  double ratio = large / small;
  if (ratio > kMaxRatio) {
    ratio = kMaxRatio;
    out.status = Status::out_of_range;
  }
  const double kp = ratio < 1.0 + 1e-13 ? 1.0 : std::exp(solve_log_k_complement(ratio));
  const EllipticIntegrals ell = elliptic_integrals(kp);
  const double long_axis =
      std::cbrt(3.0 * ell.k_minus_e_over_k2 / (2.0 * kPi * e_star_mpa * small));
  const double short_axis = long_axis * kp;
  HertzShape<double>& s = out.value;
  if (a_curv_per_mm <= b_curv_per_mm) {
    s.a_unit_mm = long_axis;
    s.b_unit_mm = short_axis;
  } else {
    s.a_unit_mm = short_axis;
    s.b_unit_mm = long_axis;
  }
  s.approach_unit_mm = 3.0 * ell.k / (2.0 * kPi * e_star_mpa * long_axis);
  s.curvature_ratio = b_curv_per_mm / a_curv_per_mm;
  return out;
}

template <typename T>
HertzPatch<T> hertz_patch(const HertzShape<T>& shape, T load_n) noexcept {
  HertzPatch<T> p;
  if (!(load_n > T{0})) {
    return p;
  }
  const T c = cube_root(load_n);
  p.a_mm = shape.a_unit_mm * c;
  p.b_mm = shape.b_unit_mm * c;
  p.approach_mm = shape.approach_unit_mm * c * c;
  constexpr T kPiT = static_cast<T>(kPi);
  p.p_mean_mpa = load_n / (kPiT * p.a_mm * p.b_mm);
  p.p_max_mpa = T{1.5} * p.p_mean_mpa;
  return p;
}

template <typename T>
T hertz_load_for_approach(const HertzShape<T>& shape, T approach_mm) noexcept {
  if (!(approach_mm > T{0}) || !(shape.approach_unit_mm > T{0})) {
    return T{0};
  }
  const T u = approach_mm / shape.approach_unit_mm;
  return u * std::sqrt(u);
}

template HertzPatch<float> hertz_patch<float>(const HertzShape<float>&, float) noexcept;
template HertzPatch<double> hertz_patch<double>(const HertzShape<double>&, double) noexcept;
template float hertz_load_for_approach<float>(const HertzShape<float>&, float) noexcept;
template double hertz_load_for_approach<double>(const HertzShape<double>&, double) noexcept;

}  // namespace tread::rail
