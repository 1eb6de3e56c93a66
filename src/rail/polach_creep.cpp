#include "rail/polach_creep.hpp"

#include <cmath>

namespace tread::rail {
namespace {

template <typename T>
T magnitude(T x, T y) noexcept {
  return std::sqrt(x * x + y * y);
}

/// Polach's saturation function: F / (2 mu Q / pi) for the stress gradient eps.
template <typename T>
T saturation(T eps, T k_adhesion, T k_slip) noexcept {
  const T ea = k_adhesion * eps;
  return ea / (T{1} + ea * ea) + std::atan(k_slip * eps);
}

}  // namespace

template <typename T>
T polach_friction(const PolachParameters<T>& p, T slip_velocity_m_s) noexcept {
  if (!(p.b_s_per_m > T{0}) || !(p.a_ratio < T{1} || p.a_ratio > T{1})) {
    return p.mu0;  // no fall with slip velocity
  }
  const T w = std::abs(slip_velocity_m_s);
  return p.mu0 * ((T{1} - p.a_ratio) * std::exp(-p.b_s_per_m * w) + p.a_ratio);
}

template <typename T>
CreepForce<T> polach_creep(const CreepContact<T>& k, const Creepage<T>& s, T speed_m_s,
                           const PolachParameters<T>& p) noexcept {
  CreepForce<T> out;
  const T q = k.normal_n;
  if (!(q > T{0}) || !(k.a_mm > T{0}) || !(k.b_mm > T{0})) {
    return out;
  }
  constexpr T kPi = static_cast<T>(3.14159265358979323846);
  // Spin-corrected lateral creepage (enters the creepage magnitude only).
  const T eta_spin = s.eta + s.phi_per_mm * k.a_mm;
  const T eta_c = std::abs(eta_spin) > std::abs(s.eta) ? eta_spin : s.eta;
  const T s_c = magnitude(s.xi, eta_c);
  if (!(s_c > T{0})) {
    return out;
  }
  const T mu = polach_friction(p, s_c * speed_m_s);
  const T mu_q = mu * q;
  if (!(mu_q > T{0})) {
    return out;
  }
  // Kalker's coefficient along the creepage direction, from the creepages without spin.
  const T s_plain = magnitude(s.xi, s.eta);
  const T c_jj = s_plain > T{0} ? magnitude(k.c.c11 * s.xi, k.c.c22 * s.eta) / s_plain : T{0};
  const T g_ab = k.g_mpa * k.a_mm * k.b_mm;
  const T eps = kPi / T{4} * g_ab * c_jj * s_c / mu_q;
  const T f = T{2} * mu_q / kPi * saturation(eps, p.k_adhesion, p.k_slip);
  const T inv_s_c = T{1} / s_c;
  out.fx_n = -f * s.xi * inv_s_c;
  out.fy_n = -f * s.eta * inv_s_c;

  // Lateral force from spin (Polach 1999).
  const T c_len = std::sqrt(k.a_mm * k.b_mm);
  const T k_m = T{1} + static_cast<T>(6.3) * (T{1} - std::exp(-k.a_mm / k.b_mm));
  const T eps_spin =
      T{8} / T{3} * k.g_mpa * k.b_mm * c_len * k.c.c23 * std::abs(eta_c) / (mu_q * k_m);
  const T e2 = eps_spin * eps_spin;
  const T inv_e2p1 = T{1} / (e2 + T{1});
  const T delta = (e2 - T{1}) * inv_e2p1;
  // 1 - delta^2 = (2 eps / (eps^2 + 1))^2, so (1 - delta^2)^(3/2) needs no root.
  const T root = T{2} * eps_spin * inv_e2p1;
  const T bracket =
      -eps_spin * (delta * delta * delta / T{3} - delta * delta / T{2} + T{1} / T{6}) +
      root * root * root / T{3};
  out.fy_n -= T{9} / T{16} * k.a_mm * mu_q * k_m * bracket * s.phi_per_mm * inv_s_c;
  // The spin term adds to the saturated force: keep the total within Coulomb's mu Q.
  T f_sat = magnitude(out.fx_n, out.fy_n);
  if (f_sat > mu_q) {
    out.fx_n *= mu_q / f_sat;
    out.fy_n *= mu_q / f_sat;
    f_sat = mu_q;
  }

  // Spin moment: Kalker's linear moment scaled like the force (kalker_linear, sharing c).
  const T g_c2 = k.g_mpa * k.a_mm * k.b_mm;
  const T g_c3 = g_c2 * c_len;
  const CreepForce<T> lin{-g_c2 * k.c.c11 * s.xi,
                          -g_c2 * k.c.c22 * s.eta - g_c3 * k.c.c23 * s.phi_per_mm,
                          g_c3 * k.c.c23 * s.eta - g_c3 * c_len * k.c.c33 * s.phi_per_mm};
  const T f_lin = magnitude(lin.fx_n, lin.fy_n);
  const T scale = f_lin > f_sat ? f_sat / f_lin : T{1};
  out.mz_nmm = lin.mz_nmm * scale;
  return out;
}

template CreepForce<float> polach_creep<float>(const CreepContact<float>&, const Creepage<float>&,
                                               float, const PolachParameters<float>&) noexcept;
template CreepForce<double> polach_creep<double>(const CreepContact<double>&,
                                                 const Creepage<double>&, double,
                                                 const PolachParameters<double>&) noexcept;
template float polach_friction<float>(const PolachParameters<float>&, float) noexcept;
template double polach_friction<double>(const PolachParameters<double>&, double) noexcept;

}  // namespace tread::rail
