#include "rail/fastsim.hpp"

#include <cmath>

namespace tread::rail {
namespace {

int clamp_count(int n) noexcept {
  return n < 1 ? 1 : (n > 400 ? 400 : n);
}

}  // namespace

template <typename T>
FastsimResult<T> fastsim(const CreepContact<T>& k, const Creepage<T>& s, T mu,
                         const FastsimGrid& grid) noexcept {
  FastsimResult<T> out;
  const T a = k.a_mm;
  const T b = k.b_mm;
  const T n = k.normal_n;
  if (!(n > T{0}) || !(a > T{0}) || !(b > T{0}) || !(k.g_mpa > T{0}) || !(mu >= T{0})) {
    return out;
  }
  constexpr T kPi = static_cast<T>(3.14159265358979323846);
  const T g = k.g_mpa;
  const T l1 = T{8} * a / (T{3} * g * k.c.c11);
  const T l2 = T{8} * a / (T{3} * g * k.c.c22);
  const T l3 = kPi * a * std::sqrt(a / b) / (T{4} * g * k.c.c23);
  const int nx = clamp_count(grid.nx);
  const int ny = clamp_count(grid.ny);
  const bool parabolic = grid.bound == TractionBound::parabolic;
  const T p_scale = parabolic ? T{2} * n / (kPi * a * b) : T{3} * n / (T{2} * kPi * a * b);
  const T dy = T{2} * b / static_cast<T>(ny);
  T fx = T{0};
  T fy = T{0};
  T mz = T{0};
  T adhesion_area = T{0};
  T total_area = T{0};
  for (int j = 0; j < ny; ++j) {
    const T y = -b + (static_cast<T>(j) + T{0.5}) * dy;
    const T yb = y / b;
    const T aj = a * std::sqrt(T{1} - yb * yb);
    const T dx = T{2} * aj / static_cast<T>(nx);
    const T wx = s.xi / l1 - s.phi_per_mm * y / l3;  // dp_x/dx (per unit x, without the phi x term)
    T px = T{0};
    T py = T{0};
    T x_boundary = aj;   // where the last update was taken
    T step = dx / T{2};  // leading edge to the first centre
    for (int i = 0; i < nx; ++i) {
      const T x = aj - (static_cast<T>(i) + T{0.5}) * dx;
      const T x_mid = T{0.5} * (x_boundary + x);
      px -= step * wx;
      py -= step * (s.eta / l2 + s.phi_per_mm * x_mid / l3);
      x_boundary = x;
      step = dx;
      const T xa = x / a;
      const T rest = T{1} - xa * xa - yb * yb;
      const T pn = rest > T{0} ? p_scale * (parabolic ? rest : std::sqrt(rest)) : T{0};
      const T bound = mu * pn;
      const T p = std::sqrt(px * px + py * py);
      if (p > bound) {
        const T f = p > T{0} ? bound / p : T{0};
        px *= f;
        py *= f;
      } else {
        adhesion_area += dx * dy;
      }
      total_area += dx * dy;
      fx += px * dx * dy;
      fy += py * dx * dy;
      mz += (x * py - y * px) * dx * dy;
    }
  }
  out.force = {fx, fy, mz};
  out.adhesion_fraction = adhesion_area / total_area;
  return out;
}

template FastsimResult<float> fastsim<float>(const CreepContact<float>&, const Creepage<float>&,
                                             float, const FastsimGrid&) noexcept;
template FastsimResult<double> fastsim<double>(const CreepContact<double>&, const Creepage<double>&,
                                               double, const FastsimGrid&) noexcept;

}  // namespace tread::rail
