#pragma once
// Flange climbing: Nadal's limit (1896) and the Y/Q quotient of a wheel.
//
// A wheel whose flange touches the rail at contact angle delta, with friction coefficient mu,
// starts to climb when the quotient of the lateral force Y (rail on wheel, toward the track centre)
// and the vertical force Q reaches
//     (Y/Q)_lim = (tan(delta) - mu) / (1 + mu tan(delta))  ( = tan(delta - atan(mu)) ),
// e.g. delta = 70 deg, mu = 0.36: 1.200, the value behind the usual Y/Q < 1.2 limit.
//
// Y and Q of a wheel are summed over its contact points from each point's normal force N, contact
// angle gamma (> 0 where the radius grows toward the flange) and the lateral creep force T in the
// contact plane (on the wheel, along the contact tangent that points away from the track centre and
// up the flange):
//     Y = sum(N sin(gamma) - T cos(gamma)),   Q = sum(N cos(gamma) + T sin(gamma)).
// At the climbing limit T = mu N on the flange point, and Y/Q is Nadal's value.

#include <cmath>

#include "core/status.hpp"

namespace tread::rail {

/// Nadal's limit. invalid_argument (value 0) for delta outside (0, 90 deg) or mu < 0 / NaN.
template <typename T>
Result<T> nadal_limit(T flange_angle_rad, T mu) noexcept {
  constexpr T kHalfPi = static_cast<T>(1.57079632679489661923);
  if (!(flange_angle_rad > T{0} && flange_angle_rad < kHalfPi) || !(mu >= T{0})) {
    return {T{0}, Status::invalid_argument};
  }
  const T t = std::tan(flange_angle_rad);
  return {(t - mu) / (T{1} + mu * t), Status::ok};
}

/// A wheel's lateral and vertical force in the track plane (N).
template <typename T>
struct WheelYQ {
  T y_n{};
  T q_n{};
};

/// Adds one contact point's forces to a wheel's Y and Q.
template <typename T>
void add_contact_point(WheelYQ<T>& wheel, T normal_n, T gamma_rad, T lateral_creep_n) noexcept {
  const T s = std::sin(gamma_rad);
  const T c = std::cos(gamma_rad);
  wheel.y_n += normal_n * s - lateral_creep_n * c;
  wheel.q_n += normal_n * c + lateral_creep_n * s;
}

/// Y/Q against Nadal's limit at the flange angle: margin = limit - Y/Q (> 0: below the limit).
template <typename T>
struct DerailmentCheck {
  T y_over_q{};
  T limit{};
  T margin{};
};

/// out_of_range (quotient 0, margin = limit) when Q <= 0 (the wheel has lifted: no quotient);
/// invalid_argument from nadal_limit.
template <typename T>
Result<DerailmentCheck<T>> derailment_check(const WheelYQ<T>& wheel, T flange_angle_rad,
                                            T mu) noexcept {
  const Result<T> limit = nadal_limit(flange_angle_rad, mu);
  Result<DerailmentCheck<T>> out;
  out.value.limit = limit.value;
  if (!limit.ok()) {
    out.status = limit.status;
    return out;
  }
  if (!(wheel.q_n > T{0}) || !std::isfinite(wheel.y_n)) {
    out.value.margin = limit.value;
    out.status = Status::out_of_range;
    return out;
  }
  out.value.y_over_q = wheel.y_n / wheel.q_n;
  out.value.margin = limit.value - out.value.y_over_q;
  return out;
}

}  // namespace tread::rail
