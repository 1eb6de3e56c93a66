#pragma once
// UIC 510-2 / DIN 5573 closed form of the S1002 wheel profile (h = 28, e = 32.5), "courtesy of
// Dr. H. Netter, DLR": F(S) per section, S lateral from D0 (+ field side), F + toward the flange
// tip. The sign pattern of each polynomial is written into the coefficients below, so
// F(S) = Σ c[i] S^i. Source and checks: the rail definitions in data/PROVENANCE.md §1.

#include <array>

namespace tread::profile::uic_s1002 {

/// Section A (outer tread 1:15), S ∈ [32.15796, 60]: F = kAA - kBA S.
inline constexpr double kAA = 1.364323640;
inline constexpr double kBA = 0.066666667;
/// Section B (tread), S ∈ [-26, 32.15796].
inline constexpr std::array<double, 9> kB = {0.0,
                                             -3.358537058e-02,
                                             1.565681624e-03,
                                             -2.810427944e-05,
                                             5.844240864e-08,
                                             -1.562379023e-08,
                                             5.309217349e-15,
                                             -5.957839843e-12,
                                             2.646656573e-13};
/// Section C (throat), S ∈ [-35, -26].
inline constexpr std::array<double, 8> kC = {-4.320221063e+03, -1.038384026e+03, -1.065501873e+02,
                                             -6.051367875,     -2.054332446e-01, -4.169739389e-03,
                                             -4.687195829e-05, -2.252755540e-07};
/// Junctions of the sections.
inline constexpr double kYAB = 32.15796;
inline constexpr double kYBC = -26.0;
inline constexpr double kYCD = -35.0;
/// Section D, the R13 flange root: F = kAD - sqrt(13² - (S + kCD)²) — the flange construction's
/// root arc is centred at (-kCD, kAD).
inline constexpr double kAD = 16.446;
inline constexpr double kCD = 26.210665;

}  // namespace tread::profile::uic_s1002
