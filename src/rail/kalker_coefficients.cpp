#include "rail/kalker_coefficients.hpp"

#include <cmath>
#include <cstddef>

namespace tread::rail {
namespace {

// One row of the published table: {C11, C22, C23, C33} x {nu = 0, 0.25, 0.5}.
struct Row {
  float c[4][3];
};

// a/b <= 1, g = a/b = 0.1 ... 1.0.
constexpr Row kAOverB[10] = {
    {{{2.51F, 3.31F, 4.85F},
      {2.51F, 2.52F, 2.53F},
      {0.334F, 0.473F, 0.731F},
      {6.42F, 8.28F, 11.7F}}},
    {{{2.59F, 3.37F, 4.81F},
      {2.59F, 2.63F, 2.66F},
      {0.483F, 0.603F, 0.809F},
      {3.46F, 4.27F, 5.66F}}},
    {{{2.68F, 3.44F, 4.80F},
      {2.68F, 2.75F, 2.81F},
      {0.607F, 0.715F, 0.889F},
      {2.49F, 2.96F, 3.72F}}},
    {{{2.78F, 3.53F, 4.82F},
      {2.78F, 2.88F, 2.98F},
      {0.720F, 0.823F, 0.977F},
      {2.02F, 2.32F, 2.77F}}},
    {{{2.88F, 3.62F, 4.83F},
      {2.88F, 3.01F, 3.14F},
      {0.827F, 0.929F, 1.07F},
      {1.74F, 1.93F, 2.22F}}},
    {{{2.98F, 3.72F, 4.91F}, {2.98F, 3.14F, 3.31F}, {0.930F, 1.03F, 1.18F}, {1.56F, 1.68F, 1.86F}}},
    {{{3.09F, 3.81F, 4.97F}, {3.09F, 3.28F, 3.48F}, {1.03F, 1.14F, 1.29F}, {1.43F, 1.50F, 1.60F}}},
    {{{3.19F, 3.91F, 5.05F}, {3.19F, 3.41F, 3.65F}, {1.13F, 1.25F, 1.40F}, {1.34F, 1.37F, 1.42F}}},
    {{{3.29F, 4.01F, 5.12F}, {3.29F, 3.54F, 3.82F}, {1.23F, 1.36F, 1.51F}, {1.27F, 1.27F, 1.27F}}},
    {{{3.40F, 4.12F, 5.20F}, {3.40F, 3.67F, 3.98F}, {1.33F, 1.47F, 1.63F}, {1.21F, 1.19F, 1.16F}}},
};

// a/b >= 1, g = b/a = 0.1 ... 1.0.
constexpr Row kBOverA[10] = {
    {{{10.7F, 11.7F, 12.9F},
      {10.7F, 12.8F, 16.0F},
      {12.2F, 14.6F, 18.0F},
      {0.795F, 0.526F, 0.228F}}},
    {{{6.96F, 7.78F, 8.82F},
      {6.96F, 8.14F, 9.79F},
      {5.72F, 6.63F, 7.89F},
      {0.828F, 0.601F, 0.341F}}},
    {{{5.57F, 6.34F, 7.34F},
      {5.57F, 6.40F, 7.51F},
      {3.79F, 4.32F, 5.01F},
      {0.868F, 0.674F, 0.446F}}},
    {{{4.84F, 5.57F, 6.57F},
      {4.84F, 5.48F, 6.31F},
      {2.88F, 3.24F, 3.70F},
      {0.912F, 0.747F, 0.549F}}},
    {{{4.37F, 5.10F, 6.11F},
      {4.37F, 4.90F, 5.56F},
      {2.35F, 2.62F, 2.96F},
      {0.958F, 0.819F, 0.650F}}},
    {{{4.06F, 4.78F, 5.80F},
      {4.06F, 4.50F, 5.04F},
      {2.01F, 2.23F, 2.50F},
      {1.01F, 0.892F, 0.751F}}},
    {{{3.82F, 4.54F, 5.58F},
      {3.82F, 4.21F, 4.67F},
      {1.76F, 1.95F, 2.18F},
      {1.05F, 0.965F, 0.852F}}},
    {{{3.65F, 4.36F, 5.42F}, {3.65F, 3.99F, 4.39F}, {1.58F, 1.75F, 1.94F}, {1.10F, 1.04F, 0.954F}}},
    {{{3.51F, 4.22F, 5.30F}, {3.51F, 3.81F, 4.16F}, {1.44F, 1.59F, 1.77F}, {1.16F, 1.11F, 1.06F}}},
    {{{3.40F, 4.12F, 5.20F}, {3.40F, 3.67F, 3.98F}, {1.33F, 1.47F, 1.63F}, {1.21F, 1.19F, 1.16F}}},
};

constexpr float kNuColumn[3] = {0.0F, 0.25F, 0.5F};

/// Kalker's asymptotic coefficients for slender ellipses (index 0..3 = C11, C22, C23, C33); only
/// their ratio between g and 0.1 is used. C33 on the b/a side has none: 1 (held constant).
template <typename T>
T asymptote(bool a_over_b_block, int coefficient, T g, T nu) noexcept {
  constexpr T kPi = static_cast<T>(3.14159265358979323846);
  if (a_over_b_block) {
    switch (coefficient) {
      case 0:
        return kPi * kPi / (T{4} * (T{1} - nu));
      case 1:
        return kPi * kPi / T{4};
      case 2:
        return kPi * std::sqrt(g) / (T{3} * (T{1} - nu)) *
               (T{1} + nu * (std::log(T{16} / g) - T{5}));
      default:
        return kPi * kPi / (T{16} * (T{1} - nu) * g);
    }
  }
  const T lambda = std::log(T{16} / (g * g));
  const T three_minus_ln4 = T{3} - std::log(T{4});
  switch (coefficient) {
    case 0:
      return T{2} * kPi / ((lambda - T{2} * nu) * g) *
             (T{1} + three_minus_ln4 / (lambda - T{2} * nu));
    case 1: {
      const T d = (T{1} - nu) * lambda + T{2} * nu;
      return T{2} * kPi / g * (T{1} + (T{1} - nu) * three_minus_ln4 / d) / d;
    }
    case 2:
      return T{2} * kPi / (T{3} * g * std::sqrt(g) * ((T{1} - nu) * lambda - T{2} + T{4} * nu));
    default:
      return T{1};
  }
}

/// g^p for the powers kalker_interpolation_power() returns.
template <typename T>
T power_of(T g, double p) noexcept {
  if (p < 0.25) {
    return T{1};
  }
  if (p < 0.75) {
    return std::sqrt(g);
  }
  if (p < 1.25) {
    return g;
  }
  return g * std::sqrt(g);
}

/// The three Poisson columns of one coefficient at g (interpolated or extrapolated in g).
template <typename T>
void columns_at(const Row* block, bool a_over_b_block, int coefficient, T g, T out[3]) noexcept {
  if (g <= static_cast<T>(0.1)) {
    for (int j = 0; j < 3; ++j) {
      const T nu = static_cast<T>(kNuColumn[j]);
      const T at_table = static_cast<T>(block[0].c[coefficient][j]);
      out[j] = at_table * asymptote(a_over_b_block, coefficient, g, nu) /
               asymptote(a_over_b_block, coefficient, static_cast<T>(0.1), nu);
    }
    return;
  }
  const T u = g * T{10} - T{1};  // 0 at g = 0.1, 9 at g = 1
  auto i = static_cast<int>(u);
  if (i > 8) {
    i = 8;
  }
  const T f = u - static_cast<T>(i);
  // Linear in g of C g^p, p following the coefficient's growth (see the header).
  const double p = kalker_interpolation_power(a_over_b_block, coefficient);
  const T g_lo = static_cast<T>(i + 1) / T{10};
  const T g_hi = static_cast<T>(i + 2) / T{10};
  const T w_lo = power_of(g_lo, p);
  const T w_hi = power_of(g_hi, p);
  const T w = power_of(g, p);
  for (int j = 0; j < 3; ++j) {
    const T lo = static_cast<T>(block[i].c[coefficient][j]) * w_lo;
    const T hi = static_cast<T>(block[i + 1].c[coefficient][j]) * w_hi;
    out[j] = (lo + (hi - lo) * f) / w;
  }
}

/// The parabola through 1/C at nu = 0, 0.25, 0.5, evaluated at nu.
template <typename T>
T across_nu(const T c[3], T nu) noexcept {
  const T t = nu * T{4};
  const T l0 = (t - T{1}) * (t - T{2}) / T{2};
  const T l1 = -t * (t - T{2});
  const T l2 = t * (t - T{1}) / T{2};
  return T{1} / (l0 / c[0] + l1 / c[1] + l2 / c[2]);
}

}  // namespace

double kalker_interpolation_power(bool a_over_b_block, int coefficient) noexcept {
  // a/b <= 1: C11, C22 level, C23 ~ sqrt(g), C33 ~ 1/g; b/a: C11, C22 ~ 1/g, C23 ~ g^-1.5, C33
  // level.
  constexpr double kA[4] = {0.0, 0.0, 0.5, 1.0};
  constexpr double kB[4] = {1.0, 1.0, 1.5, 0.0};
  if (coefficient < 0 || coefficient > 3) {
    return 0.0;
  }
  return a_over_b_block ? kA[coefficient] : kB[coefficient];
}

template <typename T>
KalkerCoefficients<T> kalker_coefficients(T a_over_b, T nu) noexcept {
  KalkerCoefficients<T> out;
  if (std::isnan(a_over_b) || std::isnan(nu)) {
    a_over_b = T{1};
    nu = T{0.25};
    out.extrapolated = true;
  }
  nu = nu < T{0} ? T{0} : (nu > T{0.5} ? T{0.5} : nu);
  a_over_b = a_over_b < static_cast<T>(1e-3) ? static_cast<T>(1e-3)
                                             : (a_over_b > T{1e3} ? T{1e3} : a_over_b);
  const bool a_block = a_over_b <= T{1};
  const T g = a_block ? a_over_b : T{1} / a_over_b;
  if (g < static_cast<T>(0.1)) {
    out.extrapolated = true;
  }
  const Row* block = a_block ? kAOverB : kBOverA;
  T value[4];
  for (int k = 0; k < 4; ++k) {
    T cols[3];
    columns_at(block, a_block, k, g, cols);
    value[k] = across_nu(cols, nu);
  }
  out.c11 = value[0];
  out.c22 = value[1];
  out.c23 = value[2];
  out.c33 = value[3];
  return out;
}

KalkerCoefficients<double> kalker_table_entry(bool a_over_b_block, int row,
                                              int nu_column) noexcept {
  KalkerCoefficients<double> out;
  if (row < 0 || row > 9 || nu_column < 0 || nu_column > 2) {
    out.extrapolated = true;
    return out;
  }
  const Row& r = (a_over_b_block ? kAOverB : kBOverA)[row];
  out.c11 = static_cast<double>(r.c[0][nu_column]);
  out.c22 = static_cast<double>(r.c[1][nu_column]);
  out.c23 = static_cast<double>(r.c[2][nu_column]);
  out.c33 = static_cast<double>(r.c[3][nu_column]);
  return out;
}

template KalkerCoefficients<float> kalker_coefficients<float>(float, float) noexcept;
template KalkerCoefficients<double> kalker_coefficients<double>(double, double) noexcept;

}  // namespace tread::rail
