// MF 6.2 loaded radius above FZMAX (useMode 1xx). MFeval 4.x solves MF 6.2's Rl for the load as
// given (its calculateRhoRl62 takes the unlimited uFz), while the forces, moments and Cz see the
// load limited to FZMAX; MF 6.1 solves its quadratic for the limited load, so its Rl stops
// changing at FZMAX. There is no MATLAB/Octave here to run MFeval, so the expected MF 6.2 Rl is
// derived independently: the MF-Tyre 6.2 vertical force Fz62(Rl) (deflection with the camber and
// lateral-force terms, written out below from the equations, not from tread's fz62) is solved for
// Rl by a secant iteration in double, with ω, Fx, Fy and γ taken from the evaluation.
// Before, tread solved for the limited load: with MagicFormula62_Parameters.tir at Fz = 27 000 N
// (1.5·FZMAX), κ = α = γ = 0, Vx = 16.7 m/s, Rl was 0.34050 m instead of 0.31827 m (22 mm high).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_fixed.hpp"
#include "mf/mf_lanes.hpp"
#include "mf_fixed_input.hpp"
#include "shipped_mf_tyres.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

MfParameters<double> load(const char* name) {
  return tyre::load_mf_parameters(testing::tyre_file(name)).params;
}

/// Romega at a wheel speed ω: R0·(Q_RE0 + Q_V1·(ω·R0/V0)²), as calculateRe has it.
template <typename P>
P romega_at(const MfParameters<P>& p, P omega) {
  const P w = omega * p.unloaded_radius_m / p.longvl_mps;
  return p.unloaded_radius_m * (p.q_re0 + p.q_v1 * w * w);
}

/// The MF-Tyre 6.2 vertical force at loaded radius `rl` (MFeval's calculateFz62 equations).
double fz62_reference(const MfParameters<double>& p, double gamma, double omega, double dpi,
                      double fx, double fy, double rl) {
  const double r0 = p.unloaded_radius_m;
  const double fz0 = p.fnomin_n;
  const double romega =
      r0 * (p.q_re0 + p.q_v1 * (omega * r0 / p.longvl_mps) * (omega * r0 / p.longvl_mps));
  const double a = p.vertical_stiffness_npm * r0 / fz0;
  const double q_fz1 = std::sqrt(a * a - 4.0 * p.q_fz2);
  const double sfyg =
      (p.q_fys1 + p.q_fys2 * (rl / romega) + p.q_fys3 * (rl / romega) * (rl / romega)) * gamma;
  const double rho_free = std::max(romega - rl, 0.0);
  const double rtw = (1.075 - 0.5 * p.aspect_ratio) * p.width_m;
  double rho_camber = 0.0;
  if (std::fabs(gamma) > 0.0) {
    const double num = (p.q_cam1 * rl + p.q_cam2 * rl * rl) * gamma;
    const double den = (p.q_cam1 * romega + p.q_cam2 * romega * romega) * gamma;
    // Q_CAM1 = Q_CAM2 = 0 (MF 5.2, PAC2002 files): 0/0, which MFeval turns into 0.
    if (std::fabs(den) > 0.0) {
      rho_camber = (num / den) * (num / den) * (rtw / 8.0) * std::fabs(std::tan(gamma));
    }
  }
  rho_camber -= p.q_cam3 * rho_free * std::fabs(gamma);
  const double rho = std::max(rho_free + rho_camber, 0.0);
  const double fcy = std::pow(rho / r0, p.q_fcy2) * p.q_fcy * (fy - sfyg) / fz0;
  const double fcx = p.q_fcx * fx / fz0;
  const double fcorr =
      (1.0 + p.q_v2 * (r0 / p.longvl_mps) * std::fabs(omega) - fcx * fcx - fcy * fcy) *
      (1.0 + p.pfz1 * dpi);
  return fcorr * (q_fz1 * (rho / r0) + p.q_fz2 * (rho / r0) * (rho / r0)) * fz0;
}

/// Rl with fz62_reference(Rl) = fz_target: secant from 0.95·R0 and R0.
double rl_reference(const MfParameters<double>& p, const MfOutput<double>& out, double fz_target) {
  const double dpi = (out.p_pa - p.nompres_pa) / p.nompres_pa;
  const auto f = [&](double rl) {
    return fz62_reference(p, out.gamma_rad, out.omega_radps, dpi, out.fx_n, out.fy_n, rl) -
           fz_target;
  };
  double x0 = 0.95 * p.unloaded_radius_m;
  double x1 = p.unloaded_radius_m;
  double y0 = f(x0);
  double y1 = f(x1);
  for (int i = 0; i < 100 && std::fabs(y1) > 1e-9 * p.fnomin_n; ++i) {
    const double x2 = x1 - (x1 - x0) * y1 / (y1 - y0);
    x0 = x1;
    y0 = y1;
    x1 = x2;
    y1 = f(x1);
  }
  return x1;
}

MfInput<double> at_load(double fz_n, double kappa, double alpha, double gamma) {
  MfInput<double> in;
  in.fz_n = fz_n;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.gamma_rad = gamma;
  in.vx_mps = 16.7;
  return in;
}

constexpr std::array<double, 6> kLoads = {6000.0, 17999.0, 18000.0, 20000.0, 24000.0, 27000.0};

TEST(Mf62LoadedRadius, AboveFzmaxSolvedForTheLoadAsGiven) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  ASSERT_EQ(p.fit_type, FitType::mf62);
  ASSERT_DOUBLE_EQ(p.fzmax_n, 18000.0);
  for (const int mode : {111, 121, 211}) {
    const MfOptions o = options_from_use_mode(mode).value;
    for (const double fz : kLoads) {
      for (const auto& slip :
           {std::array<double, 3>{0, 0, 0}, std::array<double, 3>{0.05, 0.1, 0.02},
            std::array<double, 3>{-0.1, -0.05, -0.03}}) {
        const MfOutput<double> out = evaluate(p, at_load(fz, slip[0], slip[1], slip[2]), o);
        ASSERT_EQ(out.status, Status::ok);
        const double expected = rl_reference(p, out, fz);
        EXPECT_NEAR(out.rl_m, expected, 1e-9)
            << "mode " << mode << " Fz " << fz << " kappa " << slip[0] << " alpha " << slip[1];
        // Cz with the load the forces see (limited with the limits on), as MFeval.
        const double fz_limited = o.use_limits ? std::min(fz, p.fzmax_n) : fz;
        EXPECT_NEAR(out.cz_npm, fz_limited / out.rho_m, 1e-6 * out.cz_npm);
      }
    }
  }
}

TEST(Mf62LoadedRadius, KeepsFallingAboveFzmaxWhileMf61Stops) {
  const MfParameters<double> p62 = load("MagicFormula62_Parameters.tir");
  const MfParameters<double> p61 = load("MagicFormula61_Parameters.tir");
  const MfOptions o = options_from_use_mode(111).value;
  const auto rl = [&o](const MfParameters<double>& p, double fz) {
    return evaluate(p, at_load(fz, 0, 0, 0), o).rl_m;
  };
  // MF 6.1: the quadratic in the limited load, as MFeval's calculateRhoRl61 (only Romega still
  // grows a little with ω, which comes from Re at the given load).
  EXPECT_NEAR(rl(p61, 27000.0), rl(p61, 18000.0), 5e-5);
  // MF 6.2: about Δ Fz / Cz lower (Cz ≈ 3.2e5 N/m here): 20 mm at 1.5·FZMAX.
  const double drop = rl(p62, 18000.0) - rl(p62, 27000.0);
  EXPECT_GT(drop, 0.015);
  EXPECT_LT(drop, 0.030);
  // Below FZMAX the two files (same tyre) agree to a fraction of a millimetre.
  EXPECT_NEAR(rl(p62, 6000.0), rl(p61, 6000.0), 1e-4);
}

// Halley's error estimate K·step³ with K ≈ step / previous³ holds only once both steps are in the
// cubic regime. Here (a light wheel with |Fy| ≫ Fz) a Halley step of 0.12 m, its factor on
// Newton's 1.28, was followed by one of 1.3 mm that the estimate called settled: the estimate was
// 475× low and the lanes' Rl 8e-7 m off. Settling now needs both factors within 10 % of 1.
TEST(Mf62LoadedRadius, HalleyEstimateWaitsForTheCubicRegime) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<float> pf = convert_parameters<float>(p);
  const float gamma = -0.177767F;
  const float omega = 77.1458F;
  const float dpi = -0.323997F;
  const float fx = -941.736F;
  const float fy = -5043.65F;
  const float fz = 61.9948F;
  const float romega = romega_at(pf, omega);
  const auto solved =
      detail::loaded_radius62(detail::fz62_curve(p, double{gamma}, double{omega}, double{romega},
                                                 double{dpi}, double{fx}, double{fy}),
                              double{fz});
  const auto solved4 = detail::loaded_radius62(
      detail::fz62_curve(pf, lanes::F4(gamma), lanes::F4(omega), lanes::F4(romega), lanes::F4(dpi),
                         lanes::F4(fx), lanes::F4(fy)),
      lanes::F4(fz));
  ASSERT_FALSE(solved4.fallback);
  EXPECT_NEAR(static_cast<double>(solved4.rl_m[0]), solved.rl_m, 1e-7);
}

// (1 + δ)^q's [n/n] Padé approximant in long double, its coefficients from ₂F₁(−n, −n − q; −2n; −δ)
// over ₂F₁(−n, q − n; −2n; −δ) (term by term, independently of fz62_curve's closed forms).
long double pade(int n, long double q, long double delta) {
  long double num = 1.0L;
  long double den = 1.0L;
  long double tn = 1.0L;
  long double td = 1.0L;
  const long double nn = n;
  for (int k = 0; k < n; ++k) {
    const long double kk = k;
    tn *= (-nn + kk) * (-nn - q + kk) / ((-2.0L * nn + kk) * (kk + 1.0L)) * -delta;
    td *= (-nn + kk) * (-nn + q + kk) / ((-2.0L * nn + kk) * (kk + 1.0L)) * -delta;
    num += tn;
    den += td;
  }
  return num / den;
}

template <typename T>
double lane_value(const T& v, int k) {
  if constexpr (detail::is_lanes<T>) {
    return static_cast<double>(v[k]);
  } else {
    static_cast<void>(k);
    return static_cast<double>(v);
  }
}

// fz62_pow: near its memo (b, b^q) it takes (x/b)^q from a Padé approximant wherever the
// approximant's error bound is below half of the type's ε, else pow, which becomes the new memo:
// [3/3] in float and double (|δ| < 0.3), [5/5] on lanes (pow_floor < δ < 1.5; the floor is −0.5
// where |q| ≤ 1 and nearer 0 beyond, where rounding grows). Over q from −10 to 10
// (whole values too; for whole q in [−3, 3] ([−5, 5] on lanes) the approximant is exact, and q
// near those, where its error term is tiny, tests the reach) and steps δ = x/b − 1 from −0.8 to
// 1.6 (on lanes four different steps in the four lanes of a call):
//   - where the approximant was taken, its truncation error alone (the approximant in long double
//     at the δ the type computed, against (1 + δ)^q) is at most half of ε: 6e-8 in float and on
//     lanes, 1.1e-16 in double;
//   - each result is within that plus the arithmetic's rounding of x^q (from long double): the
//     rounding of δ = x·(1/b) − 1, amplified by |q|, and of b^q·N/D, within (8 + |q|) ε;
//   - where pow was taken the result is pow's and the memo moved to x (only in that lane);
//   - where the approximant was taken its denominator D (fz62_pow_ratio's den) is positive (fz62
//     returns Fz62 − Fz and its derivatives times D and the solve reads their signs), and where
//     pow was taken it is 1.
// For MagicFormula62's q = −0.9502 the approximant (not pow) serves every |δ| < 0.3 in float and
// −0.49 ≤ δ ≤ 1.3 on lanes (the bound's reach there is −0.57 … 1.34); the binomial series to δ⁶
// they replaced served only |δ| < 0.095.
template <typename T, typename P>
void check_pow_near_memo(const MfParameters<P>& base_params, double half_epsilon, double epsilon,
                         double reach_below, double reach_above) {
  constexpr int kOrder = detail::kPowPade55<T> ? 5 : 3;
  constexpr int kWidth = detail::is_lanes<T> ? 4 : 1;
  int approximated = 0;
  int computed = 0;
  // MagicFormula62's first (−0.9502), then q near the whole values where the error term vanishes.
  std::vector<double> qs{2.0 * static_cast<double>(base_params.q_fcy2),
                         1e-4,
                         -1e-3,
                         1.0 + 1e-4,
                         -2.0 + 1e-3,
                         3.0 - 1e-4,
                         -4.0 + 1e-4,
                         5.0 - 1e-3};
  for (int qi = -40; qi <= 40; ++qi) {
    for (const double offset : {0.0, 0.0123, 0.31}) {
      if (qi * 0.25 + offset <= 10.0) qs.push_back(qi * 0.25 + offset);
    }
  }
  for (std::size_t qi = 0; qi < qs.size(); ++qi) {
    const double q = qs[qi];
    MfParameters<P> p = base_params;
    p.q_fcy2 = static_cast<P>(q / 2.0);
    const auto c =
        detail::fz62_curve(p, T(0.01F), T(80.0F), T(0.39F), T(0.0F), T(100.0F), T(2000.0F));
    const double q_t = static_cast<double>(c.pow_q);  // q as the type holds it
    const double tolerance = half_epsilon + (8.0 + std::fabs(q_t)) * epsilon;
    for (const double b : {1e-4, 0.02, 0.3}) {
      if (std::fabs(q * std::log10(b)) > 30.0) continue;  // b^q outside float's normal range
      for (int di = -80; di <= 160; di += kWidth) {
        const T base = T(static_cast<P>(b));
        T x = base;
        if constexpr (kWidth == 1) {
          x = T(static_cast<P>(b * (1.0 + di * 0.01)));
        } else {
          x = T(lanes::FloatVec<4>{static_cast<P>(b * (1.0 + di * 0.01)),
                                   static_cast<P>(b * (1.0 + (di + 1) * 0.01)),
                                   static_cast<P>(b * (1.0 + (di + 2) * 0.01)),
                                   static_cast<P>(b * (1.0 + (di + 3) * 0.01))});
        }
        detail::Fz62PowMemo<T> memo;
        memo.base = base;
        memo.inv_base = T(1) / base;
        memo.value = T(std::pow(static_cast<P>(b), static_cast<P>(q_t)));
        const T delta = x * memo.inv_base - T(1);  // as fz62_pow_ratio computes it
        detail::Fz62PowMemo<T> memo_ratio = memo;
        const detail::Fz62Power<T> ratio = detail::fz62_pow_ratio(c, x, memo_ratio, T(0) <= T(0));
        const T got = detail::fz62_pow(c, x, memo);
        using std::pow;  // the type's own pow (on lanes found by argument-dependent lookup)
        const T computed_pow = T(pow(x, T(static_cast<P>(q_t))));
        for (int k = 0; k < kWidth; ++k) {
          const auto xk = static_cast<P>(lane_value(x, k));
          const long double exact =
              std::pow(static_cast<long double>(xk), static_cast<long double>(q_t));
          const long double rel =
              std::fabs(static_cast<long double>(lane_value(got, k)) / exact - 1.0L);
          const double step = (di + k) * 0.01;
          SCOPED_TRACE("q " + std::to_string(q_t) + " b " + std::to_string(b) + " δ " +
                       std::to_string(step));
          const double moved_to = lane_value(memo.base, k);
          const auto held = static_cast<double>(static_cast<P>(b));
          const bool kept = !(moved_to < held) && !(moved_to > held);  // the memo did not move
          if (kept) {
            ++approximated;
            const long double d = lane_value(delta, k);
            const long double truncation =
                std::fabs(pade(kOrder, static_cast<long double>(q_t), d) /
                              std::pow(1.0L + d, static_cast<long double>(q_t)) -
                          1.0L);
            EXPECT_LE(static_cast<double>(truncation), half_epsilon);
            EXPECT_LE(static_cast<double>(rel), tolerance);
            // fz62 scales Fz62 − Fz and its derivatives by D and reads their signs: D > 0.
            EXPECT_GT(lane_value(ratio.den, k), 0.0);
          } else {
            ++computed;
            EXPECT_EQ(moved_to, static_cast<double>(xk));
            EXPECT_EQ(lane_value(got, k), lane_value(computed_pow, k));
            EXPECT_EQ(lane_value(ratio.den, k), 1.0);  // pow's value, as it is
          }
          if (qi == 0 && step >= reach_below - 1e-9 && step <= reach_above + 1e-9) {
            EXPECT_TRUE(kept) << "pow taken within the approximation's reach";
          }
        }
      }
    }
  }
  EXPECT_GT(approximated, 1000);
  EXPECT_GT(computed, 1000);
}

TEST(Mf62LoadedRadius, PowNearItsMemoWithinHalfAnEpsilon) {
  MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  check_pow_near_memo<double>(p, 1.1e-16, 2.2e-16, 0.0, 0.0);
  const MfParameters<float> pf = convert_parameters<float>(p);
  check_pow_near_memo<float>(pf, 6e-8, 1.2e-7, -0.29, 0.29);
  check_pow_near_memo<lanes::F4>(pf, 6e-8, 1.2e-7, -0.49, 1.3);
}

/// The float and lanes start (detail::quadratic_deflection) against the root of its quadratic in
/// double: the third convergent of the root's continued fraction, below the root by at most u⁴
/// of it (u = Q_FZ2·Fz/(E·Q_FZ1²)) and never above it, the root itself where Q_FZ2 = 0, over
/// random curves far wider than any tyre's (Q_FZ1 2–40, Q_FZ2 0–150, loads 1 N–300 kN).
template <typename T>
void check_start_convergent() {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> q1(2.0, 40.0);
  std::uniform_real_distribution<double> q2(0.0, 150.0);
  std::uniform_real_distribution<double> log_fz(0.0, 5.5);
  std::uniform_real_distribution<double> base(0.3, 1.6);
  std::uniform_real_distribution<double> scale(1e3, 6e4);
  std::uniform_real_distribution<double> fcy(0.0, 0.5);
  int checked = 0;
  int exact = 0;
  double worst_share = 0.0;  // the most of its bound u⁴ an error below the root used
  for (int i = 0; i < 100000; ++i) {
    detail::Fz62Curve<T, float> c{};
    const auto q_fz1 = static_cast<float>(q1(rng));
    const bool linear = i % 10 == 0;
    const float q_fz2 = linear ? 0.0F : static_cast<float>(q2(rng));
    const auto base_f = static_cast<float>(base(rng));
    const auto scale_f = static_cast<float>(scale(rng));
    const auto fz = static_cast<float>(std::pow(10.0, log_fz(rng)));
    const auto l = static_cast<float>(fcy(rng));
    c.q_fz1 = T(q_fz1);
    c.q_fz2 = T(q_fz2);
    c.base = T(base_f);
    c.stiffness_scale = T(scale_f);
    // The root in double, of the curve's float values.
    const double a1 = q_fz1;
    const double a2 = q_fz2;
    const double e = (double{base_f} - double{l} * double{l}) * double{scale_f};
    ASSERT_GT(e, 0.0);
    const double q = double{fz} / e;
    const double root = 2.0 * q / (a1 + std::sqrt(a1 * a1 + 4.0 * a2 * q));
    const double u = a2 * q / (a1 * a1);
    float x = 0.0F;
    if constexpr (std::is_same_v<T, float>) {
      x = detail::quadratic_deflection(c, fz, l);
    } else {
      x = detail::quadratic_deflection(c, T(fz), T(l))[0];
    }
    const double below = 1.0 - double{x} / root;
    const std::string where = "Q_FZ1 " + std::to_string(q_fz1) + ", Q_FZ2 " +
                              std::to_string(q_fz2) + ", Fz " + std::to_string(fz) + ", u " +
                              std::to_string(u);
    // Float's rounding: a few ulp of the root either way.
    const double u4 = u * u * u * u;
    EXPECT_GE(below, -1e-6) << where;
    EXPECT_LE(below, u4 + 1e-6) << where;
    if (linear) {
      EXPECT_NEAR(below, 0.0, 1e-6) << where;
      ++exact;
    } else if (u > 0.05) {
      worst_share = std::max(worst_share, below / u4);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 100000);
  EXPECT_GT(exact, 9000);
  // The bound is not loose (the error's leading term is u⁴; above u = 0.05, where float's rounding
  // no longer hides it, 3/4 of it is reached).
  EXPECT_GT(worst_share, 0.5);
}

// Four lanes keep the [5/5] Padé coefficients of the last q per thread (pade55_kept): whatever
// sequence of q a thread asks for (the same again, another, back, a NaN, ±0), each answer is
// pade55(q)'s, bit for bit; another thread starts with nothing kept and leaves this thread's q
// kept.
TEST(Mf62LoadedRadius, KeptPadeCoefficientsAreTheComputedOnes) {
  using detail::Pade55;
  // The coefficients, bit for bit (q itself may be the other zero: −0 and +0 give the same ones).
  const auto same = [](const Pade55<float>& a, const Pade55<float>& b) {
    using Floats = std::array<float, 13>;
    static_assert(sizeof(Pade55<float>) == sizeof(Floats));
    const auto fa = std::bit_cast<Floats>(a);
    const auto fb = std::bit_cast<Floats>(b);
    return std::memcmp(fa.data() + 1, fb.data() + 1, 12 * sizeof(float)) == 0;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> qs{-0.9502F, -0.9502F, 1.3F,  -0.9502F, 4.0F, nan,
                              nan,      2.0F,     -0.0F, 0.0F,     2.0F, -0.9502F};
  for (const float q : qs) {
    const Pade55<float> kept = detail::pade55_kept(q);
    const Pade55<float> computed = detail::pade55(q);
    if (std::isnan(q)) {
      EXPECT_TRUE(std::isnan(kept.q) && std::isnan(kept.n1) && std::isnan(kept.remainder));
    } else {
      EXPECT_TRUE(same(kept, computed)) << "q " << q;
    }
  }
  // Per thread: another thread starts with nothing kept and leaves this thread's q kept.
  ASSERT_TRUE(same(detail::pade55_kept(-0.9502F), detail::pade55(-0.9502F)));
  bool other_started_empty = false;
  Pade55<float> other_thread{};
  std::thread t([&] {
    other_started_empty = !detail::pade55_kept_value<float>.valid;
    other_thread = detail::pade55_kept(3.5F);
  });
  t.join();
  EXPECT_TRUE(other_started_empty);
  EXPECT_TRUE(same(other_thread, detail::pade55(3.5F)));
  EXPECT_TRUE(detail::pade55_kept_value<float>.valid);
  EXPECT_TRUE(same(detail::pade55_kept_value<float>.k, detail::pade55(-0.9502F)));
}

TEST(Mf62LoadedRadius, StartIsTheRootsThirdConvergent) {
  check_start_convergent<float>();
  check_start_convergent<lanes::F4>();
}

TEST(Mf62LoadedRadius, FloatAndFourLanesAgreeWithDouble) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<float> pf = convert_parameters<float>(p);
  const MfOptions o = options_from_use_mode(111).value;
  std::array<MfInput<float>, 4> in{};
  const std::array<double, 4> loads = {6000.0, 18000.0, 24000.0, 27000.0};
  for (std::size_t k = 0; k < 4; ++k) {
    in[k].fz_n = static_cast<float>(loads[k]);
    in[k].kappa = 0.02F;
    in[k].alpha_rad = 0.05F;
    in[k].gamma_rad = 0.01F;
    in[k].vx_mps = 16.7F;
  }
  std::array<MfOutput<float>, 4> four{};
  const std::array<MountedSide, 4> sides{};
  evaluate_four(pf, in, o, sides, four);
  for (std::size_t k = 0; k < 4; ++k) {
    const MfOutput<double> d = evaluate(p, at_load(loads[k], 0.02, 0.05, 0.01), o);
    const MfOutput<float> f = evaluate(pf, in[k], o);
    // Float: Fz62 is solved to float's resolution; Fx/Fy differ by ~1e-4 relative.
    EXPECT_NEAR(f.rl_m, d.rl_m, 2e-5) << loads[k];
    EXPECT_NEAR(four[k].rl_m, d.rl_m, 2e-5) << loads[k];
    EXPECT_EQ(four[k].status, Status::ok);
  }
}

// The loaded radius is solved by a safeguarded Newton (Halley) iteration (detail::loaded_radius62)
// in a bounded number of steps. Over the whole envelope the model accepts (loads 0 … 10·FZMAX, |γ|
// up to 1.5707 rad, slips, speeds and pressures far outside any measured range), for every tyre
// file that takes this path (MF 6.2, MF 5.2, PAC2002), it must converge within its step budget
// without the bisection fallback, to the root of the independent Fz62 above on the same branch
// (below Romega, or above it where the camber alone carries more than Fz) found by 200 halvings in
// double.
struct EnvelopePoint {
  double fz, kappa, alpha, gamma, vx, p_ratio;
};

std::vector<EnvelopePoint> envelope(const MfParameters<double>& p) {
  const double fz_top = 10.0 * std::max(p.fzmax_n, p.fnomin_n);
  const std::array<double, 13> loads = {
      0.0,           1.0,          10.0,       100.0,          300.0,
      1000.0,        3000.0,       p.fnomin_n, 2 * p.fnomin_n, p.fzmax_n,
      3 * p.fzmax_n, 0.5 * fz_top, fz_top};
  const std::array<double, 10> gammas = {-1.5707, -0.5, -0.1, -0.03, 0.0,
                                         0.002,   0.01, 0.05, 0.2,   1.0};
  const std::array<std::array<double, 2>, 4> slips = {
      {{0.0, 0.0}, {0.1, 0.05}, {-0.5, -0.3}, {0.02, 1.2}}};
  const std::array<double, 3> speeds = {0.5, 16.7, 60.0};
  const std::array<double, 3> pressures = {0.5, 1.0, 2.0};
  std::vector<EnvelopePoint> points;
  for (const double fz : loads)
    for (const double g : gammas)
      for (const auto& s : slips)
        for (const double v : speeds)
          for (const double pr : pressures) points.push_back({fz, s[0], s[1], g, v, pr});
  return points;
}

/// Rl with the least deflection: loading the tyre from Romega, the first Rl where Fz62 reaches Fz.
/// Below Romega: the largest root in [0, Romega]; above it (where the camber alone carries more
/// than Fz at Romega), the smallest in [Romega, Romega + w]. Without a root on the branch: 0 below
/// Romega (Fz beyond a fully squashed tyre), Romega above it (the camber alone carries more than
/// Fz: the free radius, not the end a tyre width above it). A scan away from Romega in steps of
/// 10 µm finds the first crossing, bisection (100 halvings) the root.
double rl_least_deflection(const MfParameters<double>& p, const MfOutput<double>& out, double dpi,
                           double fz_target) {
  const double romega = romega_at(p, out.omega_radps);
  const auto above = [&](double rl) {
    return fz62_reference(p, out.gamma_rad, out.omega_radps, dpi, out.fx_n, out.fy_n, rl) >
           fz_target;
  };
  const bool beyond = above(romega);
  const double end = beyond ? romega + p.width_m : 0.0;
  const double step = beyond ? 1e-5 : -1e-5;
  double near = romega;  // above(near) == beyond
  double far = romega;
  for (;;) {
    far = near + step;
    if (beyond ? far >= end : far <= end) {
      far = end;
      if (above(far) == beyond) return beyond ? romega : end;  // no root on this branch
      break;
    }
    if (above(far) != beyond) break;
    near = far;
  }
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (near + far);
    (above(mid) == beyond ? near : far) = mid;
  }
  return 0.5 * (near + far);
}

/// A tyre with a strong lateral term (Q_FCY 3× the sample's, Q_FCY2 = +0.35) at heavy, cornering
/// loads: loaded from Romega, Fz62 rises over Fz on a hump and falls below it again deeper in
/// (Fcy² grows with the deflection). The least-deflection root is on the hump's Romega side. The
/// start (the quadratic's root without Fcy's power, which is below 1 here) lies deeper than that
/// root; float's and the lanes' convergent never deeper than the quadratic's root (a convergent
/// above it answered 0 at the first point). At the second point double's exact start is already
/// past the hump's peak (Fz62 < Fz, rising with Rl): the search must bound the root from below by
/// it, not close on 0 (it did: Rl = 0 where the root is 0.346 m).
MfParameters<double> lateral_hump_tyre() {
  MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  p.q_fcy *= 3.0;
  p.q_fcy2 = 0.35;
  return p;
}

/// Rl of every path (double, float, four lanes) at one point of `p`, against `expected`.
void expect_every_path_finds(const MfParameters<double>& p, const MfOutput<double>& out, double dpi,
                             double fz, double expected, const std::string& where) {
  const MfParameters<float> pf = convert_parameters<float>(p);
  const double romega = romega_at(p, out.omega_radps);
  const auto solved = detail::loaded_radius62(
      detail::fz62_curve(p, out.gamma_rad, out.omega_radps, romega, dpi, out.fx_n, out.fy_n), fz);
  EXPECT_NEAR(solved.rl_m, expected, 1e-9) << where;
  // A root on the hump converges (2–7 steps here); where the hump stays below Fz the bracket closes
  // on its peak, by bisection after the Newton budget.
  EXPECT_TRUE(!(expected > 0.0) || !solved.fallback) << where;
  const auto f = [](double x) { return static_cast<float>(x); };
  const auto solvedf =
      detail::loaded_radius62(detail::fz62_curve(pf, f(out.gamma_rad), f(out.omega_radps),
                                                 f(romega), f(dpi), f(out.fx_n), f(out.fy_n)),
                              f(fz));
  EXPECT_NEAR(solvedf.rl_m, expected, 5e-7) << where << " (float)";
  EXPECT_TRUE(!(expected > 0.0) || !solvedf.fallback) << where << " (float)";
  using L = lanes::F4;
  const auto solved4 = detail::loaded_radius62(
      detail::fz62_curve(pf, L(f(out.gamma_rad)), L(f(out.omega_radps)), L(f(romega)), L(f(dpi)),
                         L(f(out.fx_n)), L(f(out.fy_n))),
      L(f(fz)));
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(solved4.rl_m[k], expected, 5e-7) << where << " (lane " << k << ")";
  }
}

TEST(Mf62LoadedRadius, StartStaysOnTheRomegaSideOfALateralHump) {
  const MfParameters<double> p = lateral_hump_tyre();
  struct Point {
    double gamma, omega, dpi, fx, fy, fz;
  };
  const Point points[] = {
      {0.13401246, 28.3820375, 0.0426966874, 4035.53298, 7977.37944, 10614.2788},
      {0.129216406, 5.88407148, -0.113713408, 3012.70172, 7791.35101, 10590.5495},
  };
  for (const Point& pt : points) {
    MfOutput<double> out{};
    out.gamma_rad = pt.gamma;
    out.omega_radps = pt.omega;
    out.fx_n = pt.fx;
    out.fy_n = pt.fy;
    const double expected = rl_least_deflection(p, out, pt.dpi, pt.fz);
    const std::string where = "gamma " + std::to_string(pt.gamma) + ", Fz " + std::to_string(pt.fz);
    ASSERT_GT(expected, 0.3) << where;
    expect_every_path_finds(p, out, pt.dpi, pt.fz, expected, where);
  }
}

/// The same tyre over loads up to and past what the hump can carry, with lateral forces of
/// 0.3–1.0·Fz, cambers, speeds, pressures and longitudinal forces: every path finds the
/// least-deflection root where the hump reaches Fz and answers 0 (the branch's end, as the
/// reference scan from Romega gives) where it does not. Points whose hump peaks within 0.5 % of Fz
/// are left out: there the root's side of the peak turns on rounding.
TEST(Mf62LoadedRadius, LateralHumpRootOrTheBranchsEnd) {
  const MfParameters<double> p = lateral_hump_tyre();
  int roots = 0;
  int ends = 0;
  for (const double gamma : {0.0, 0.1342}) {
    for (const double omega : {5.9, 28.4}) {
      for (const double dpi : {-0.11, 0.043}) {
        for (const double fx : {0.0, 3012.7}) {
          for (const double fy_share : {0.31, 0.62, 0.93}) {
            for (double fz = 2113.7; fz < 40000.0; fz *= 1.37) {
              MfOutput<double> out{};
              out.gamma_rad = gamma;
              out.omega_radps = omega;
              out.fx_n = fx;
              out.fy_n = fy_share * fz;
              const double romega = romega_at(p, omega);
              // The hump's peak on a 50 µm scan from Romega to 0.
              double peak = -std::numeric_limits<double>::infinity();
              for (double rl = romega; rl > 0.0; rl -= 5e-5) {
                peak = std::max(peak, fz62_reference(p, gamma, omega, dpi, fx, out.fy_n, rl));
              }
              if (std::abs(peak - fz) < 5e-3 * fz) continue;
              const double expected = rl_least_deflection(p, out, dpi, fz);
              std::ostringstream where;
              where << "gamma " << gamma << ", omega " << omega << ", dpi " << dpi << ", Fx " << fx
                    << ", Fy " << out.fy_n << ", Fz " << fz << ", peak " << peak;
              if (peak > fz) {
                ASSERT_GT(expected, 0.0) << where.str();
                ++roots;
              } else {
                ASSERT_EQ(expected, 0.0) << where.str();
                ++ends;
              }
              expect_every_path_finds(p, out, dpi, fz, expected, where.str());
            }
          }
        }
      }
    }
  }
  // Both kinds of point are there.
  EXPECT_GT(roots, 50);
  EXPECT_GT(ends, 50);
}

std::vector<std::string> fz62_path_tyres() {
  std::vector<std::string> names;
  for (const testing::ShippedMfTyre& shipped : testing::shipped_mf_tyre_files()) {
    if (shipped.loaded.params.fit_type != FitType::mf61) {
      names.push_back(shipped.file.filename().string());
    }
  }
  return names;
}

template <typename T>
MfInput<T> input_at(const MfParameters<double>& p, const EnvelopePoint& e) {
  MfInput<T> in;
  in.fz_n = static_cast<T>(e.fz);
  in.kappa = static_cast<T>(e.kappa);
  in.alpha_rad = static_cast<T>(e.alpha);
  in.gamma_rad = static_cast<T>(e.gamma);
  in.vx_mps = static_cast<T>(e.vx);
  in.p_pa = static_cast<T>(e.p_ratio * p.nompres_pa);
  return in;
}

/// An envelope point as loaded_radius62 sees it in float, for the four-lane check.
struct LanePoint {
  float gamma, omega, romega, dpi, fx, fy, fz_target;
  double expected;  // the least-deflection root (double)
  bool use_limits;
};

/// " steps:count[/count…]" for every step count some histogram has ("fallback" for [0]).
std::string step_histogram(const std::vector<const std::array<int, 17>*>& histograms) {
  std::string text;
  for (std::size_t k = 0; k < 17; ++k) {
    std::string counts;
    bool any = false;
    for (const std::array<int, 17>* h : histograms) {
      counts += (counts.empty() ? "" : "/") + std::to_string((*h)[k]);
      any = any || (*h)[k] != 0;
    }
    if (any) text += " " + (k == 0 ? std::string("fallback") : std::to_string(k)) + ":" + counts;
  }
  return text;
}

TEST(Mf62LoadedRadius, NewtonConvergesWithinItsBudgetOverTheEnvelope) {
  const std::vector<std::string> tyres = fz62_path_tyres();
  ASSERT_GE(tyres.size(), 4U);  // MF 6.2, MF 5.2 and the PAC2002 files
  for (const std::string& name : tyres) {
    const MfParameters<double> p = load(name.c_str());
    const MfParameters<float> pf = convert_parameters<float>(p);
    for (const int mode : {111, 211}) {
      const MfOptions o = options_from_use_mode(mode).value;
      std::array<int, 17> steps_double{};  // [0]: the bisection fallback
      std::array<int, 17> steps_float{};
      double worst_double = 0.0;
      double worst_float = 0.0;
      std::vector<LanePoint> lane_points;
      for (const EnvelopePoint& e : envelope(p)) {
        MfOutput<double> out = evaluate(p, input_at<double>(p, e), o);
        const double dpi = (out.p_pa - p.nompres_pa) / p.nompres_pa;  // P_Pa: limited
        // γ within the envelope, and with the limits on within CAMMIN … CAMMAX (out.gamma_rad is
        // the unlimited input).
        double gamma = std::clamp(e.gamma, -1.5707, 1.5707);
        if (o.use_limits) gamma = std::clamp(gamma, p.cammin_rad, p.cammax_rad);
        out.gamma_rad = gamma;
        // The load solved for: MF 6.2 the load as given (within the envelope), MF 5.2 / PAC2002
        // the load the forces see.
        const double fz_envelope = std::min(e.fz, 10.0 * std::max(p.fzmax_n, p.fnomin_n));
        const double fz_target = p.fit_type == FitType::mf62 || !o.use_limits
                                     ? fz_envelope
                                     : std::min(fz_envelope, p.fzmax_n);
        const double expected = rl_least_deflection(p, out, dpi, fz_target);
        const double romega = romega_at(p, out.omega_radps);
        const auto curve =
            detail::fz62_curve(p, gamma, out.omega_radps, romega, dpi, out.fx_n, out.fy_n);
        const auto solved = detail::loaded_radius62(curve, fz_target);
        // ρz comes from its Taylor polynomial about the last point evaluated: it is the
        // deflection at Rl.
        double unused_slope = 0.0;
        EXPECT_NEAR(solved.rho_m, detail::fz62_deflection(curve, solved.rl_m, unused_slope), 1e-15);
        EXPECT_EQ(solved.rl_m, out.rl_m) << name;
        ++steps_double[solved.fallback ? 0 : static_cast<std::size_t>(solved.newton_steps)];
        const std::string where = name + " mode " + std::to_string(mode) + " Fz " +
                                  std::to_string(e.fz) + " kappa " + std::to_string(e.kappa) +
                                  " alpha " + std::to_string(e.alpha) + " gamma " +
                                  std::to_string(e.gamma) + " Vx " + std::to_string(e.vx) + " p " +
                                  std::to_string(e.p_ratio);
        // Double: the least-deflection root to 1e-10 m, limits on or off.
        EXPECT_NEAR(out.rl_m, expected, 1e-10) << where;
        worst_double = std::max(worst_double, std::fabs(out.rl_m - expected));

        // Float: its own Fz62 (Fx, Fy, ω in float).
        const MfOutput<float> outf = evaluate(pf, input_at<float>(p, e), o);
        const float dpif = (outf.p_pa - pf.nompres_pa) / pf.nompres_pa;
        const float romegaf = romega_at(pf, outf.omega_radps);
        const auto curvef = detail::fz62_curve(pf, static_cast<float>(gamma), outf.omega_radps,
                                               romegaf, dpif, outf.fx_n, outf.fy_n);
        const auto solvedf = detail::loaded_radius62(curvef, static_cast<float>(fz_target));
        float unused_slopef = 0.0F;
        const float rhof = detail::fz62_deflection(curvef, solvedf.rl_m, unused_slopef);
        // ρz is the deflection at the root, which lies within half of float's Rl step of the Rl
        // returned (ρz is not rounded with Rl): as far as that step moves ρz, plus a few ulp of
        // ρz (two float roundings of the same quartic, about the last point and afresh).
        const float rl_step = std::nextafter(solvedf.rl_m, 1.0F) - solvedf.rl_m;
        EXPECT_NEAR(solvedf.rho_m, rhof, 1e-6F * rhof + 1e-10F + rl_step * std::fabs(unused_slopef))
            << where;
        ++steps_float[solvedf.fallback ? 0 : static_cast<std::size_t>(solvedf.newton_steps)];
        lane_points.push_back({static_cast<float>(gamma), outf.omega_radps, romegaf, dpif,
                               outf.fx_n, outf.fy_n, static_cast<float>(fz_target), expected,
                               o.use_limits});
        if (o.use_limits) {
          // Within the model's limits: no lane ever needs the fallback, and float lands on the
          // same root (its Fx, Fy differ by ~1e-4 relative; 5e-7 m is ~16 ulp of a radius).
          EXPECT_FALSE(solved.fallback) << where;
          EXPECT_FALSE(solvedf.fallback) << where;
          EXPECT_NEAR(outf.rl_m, expected, 5e-7) << where;
          worst_float = std::max(worst_float, std::fabs(double(outf.rl_m) - expected));
        }
      }
      // Four lanes (Halley's steps, as double; float takes Newton's), neighbouring envelope points
      // side by side: each lane lands on the root as float does, and within the limits no group
      // needs the fallback.
      std::array<int, 17> steps_lanes{};
      double worst_lanes = 0.0;
      for (std::size_t g = 0; g + 4 <= lane_points.size(); g += 4) {
        lanes::F4 v[7];
        bool limited = true;
        for (std::size_t k = 0; k < 4; ++k) {
          const LanePoint& l = lane_points[g + k];
          const float fields[7] = {l.gamma, l.omega, l.romega, l.dpi, l.fx, l.fy, l.fz_target};
          for (int f = 0; f < 7; ++f) v[f].v[k] = fields[f];
          limited = limited && l.use_limits;
        }
        const auto curve4 = detail::fz62_curve(pf, v[0], v[1], v[2], v[3], v[4], v[5]);
        const auto solved4 = detail::loaded_radius62(curve4, v[6]);
        lanes::F4 unused_slope4;
        const lanes::F4 rho4 = detail::fz62_deflection(curve4, solved4.rl_m, unused_slope4);
        ++steps_lanes[solved4.fallback ? 0 : static_cast<std::size_t>(solved4.newton_steps)];
        if (!limited) continue;
        EXPECT_FALSE(solved4.fallback) << name << " group " << g;
        for (std::size_t k = 0; k < 4; ++k) {
          const double err = std::fabs(static_cast<double>(solved4.rl_m[static_cast<int>(k)]) -
                                       lane_points[g + k].expected);
          EXPECT_LT(err, 5e-7) << name << " group " << g << " lane " << k;
          // As float's: within how far half an Rl step moves ρz, plus a few ulp.
          const float rho = rho4[static_cast<int>(k)];
          const float rl = solved4.rl_m[static_cast<int>(k)];
          const float rl_step = std::nextafter(rl, 1.0F) - rl;
          EXPECT_NEAR(
              solved4.rho_m[static_cast<int>(k)], rho,
              1e-6F * rho + 1e-10F + rl_step * std::fabs(unused_slope4[static_cast<int>(k)]))
              << name << " group " << g << " lane " << k;
          worst_lanes = std::max(worst_lanes, err);
        }
      }
      std::printf("%s mode %d: groups of four by steps%s; |Rl - reference| %.1e m\n", name.c_str(),
                  mode, step_histogram({&steps_lanes}).c_str(), worst_lanes);
      std::printf(
          "%s mode %d: points by steps (double/float)%s; |Rl - reference| double %.1e m, float "
          "%.1e m\n",
          name.c_str(), mode, step_histogram({&steps_double, &steps_float}).c_str(), worst_double,
          worst_float);
    }
  }
}

// Where the pressure factor of Fz62, 1 + PFZ1·dpi, is ≤ 0 (a file with PFZ1 > 1 at a low pressure,
// with the limits off: the pressure is not held at PRESMIN), the pow-free bound on Fz62(Romega)
// that decides whether Fz62(Romega) is evaluated, (1 + speed − Fx²)(1 + PFZ1·dpi)·stiffness(ρz),
// is no bound: it is ≤ 0 while Fz62(Romega) = (1 + speed − Fx² − Fcy²)(1 + PFZ1·dpi)·stiffness(ρz)
// exceeds Fz where Fcy² > 1 + speed − Fx² (large Fy, cambered). Deciding the branch from that
// bound put Rl at Romega (the end of the wrong branch) instead of the least-deflection root above
// it. Counts of one scan over loads, cambers, slips and pressures, limits off: points with a
// pressure factor ≤ 0, of those the points with the root above Romega, and the humps missed
// (below).
struct BoundScan {
  int factor_not_positive = 0;
  int beyond_romega = 0;
  int hump_missed = 0;
  double worst_float = 0.0;
};

// Rl within 1e-10 m (double) and 2e-5 m (float) of the reference wherever the pressure factor is
// positive and wherever the root lies above Romega. Known and left alone: below Romega with a
// pressure factor < 0 the tyre has a negative stiffness — Fz62 is negative at large deflections
// and positive only on a hump near Romega, where Fcy² is large — and where the hump reaches Fz the
// solver may answer Rl = 0 (its far end, evaluated when a Newton step leaves the bracket, is on
// the same side of Fz: "no root on this branch") instead of the hump's least-deflection root.
// Those points are counted, not compared.
BoundScan scan_bound(const MfParameters<double>& p, const std::vector<double>& pressures) {
  const MfParameters<float> pf = convert_parameters<float>(p);
  const MfOptions o = options_from_use_mode(211).value;  // limits off: the pressure as given
  const std::array<double, 6> loads = {100.0,      1000.0,         3000.0,
                                       p.fnomin_n, 2 * p.fnomin_n, p.fzmax_n};
  const std::array<double, 8> gammas = {-1.0, -0.5, -0.1, 0.0, 0.05, 0.1, 0.5, 1.0};
  const std::array<std::array<double, 2>, 5> slips = {
      {{0.0, 0.0}, {0.1, 0.2}, {-0.1, -0.2}, {0.0, 0.5}, {0.05, -0.5}}};
  BoundScan scan;
  for (const double fz : loads) {
    for (const double gamma : gammas) {
      for (const auto& slip : slips) {
        for (const double ratio : pressures) {
          const EnvelopePoint e{fz, slip[0], slip[1], gamma, 16.7, ratio};
          const MfOutput<double> out = evaluate(p, input_at<double>(p, e), o);
          const MfOutput<float> outf = evaluate(pf, input_at<float>(p, e), o);
          const double dpi = (out.p_pa - p.nompres_pa) / p.nompres_pa;
          const double expected = rl_least_deflection(p, out, dpi, fz);
          const double factor = 1.0 + p.pfz1 * dpi;
          const std::string where =
              "Fz " + std::to_string(fz) + " kappa " + std::to_string(slip[0]) + " alpha " +
              std::to_string(slip[1]) + " gamma " + std::to_string(gamma) + " p " +
              std::to_string(ratio) + " (1 + PFZ1·dpi = " + std::to_string(factor) + ")";
          bool beyond = false;
          const bool fails = !(factor > 0.0);
          if (fails) {
            ++scan.factor_not_positive;
            const double romega = romega_at(p, out.omega_radps);
            beyond = fz62_reference(p, out.gamma_rad, out.omega_radps, dpi, out.fx_n, out.fy_n,
                                    romega) > fz;
            if (beyond) ++scan.beyond_romega;
            if (!beyond && !(out.rl_m > 0.0) && expected > 0.0) {
              ++scan.hump_missed;
              continue;
            }
          }
          EXPECT_NEAR(out.rl_m, expected, 1e-10) << where;
          if (fails && !beyond && !(outf.rl_m > 0.0F)) continue;  // as above, in float
          EXPECT_NEAR(outf.rl_m, expected, 2e-5) << "float " << where;
          scan.worst_float = std::max(scan.worst_float, std::fabs(double(outf.rl_m) - expected));
        }
      }
    }
  }
  return scan;
}

// The lightest loads, down to a deflection of a few resolution steps of fixed point (Q31.32):
// - Fixed point's slope must stay valid: it had multiplied x' by 1/x (x = ρz/R0), which overflows
//   Q31.32 below x ≈ |x'|/2^31 ≈ 1.2e-9, and an invalid value times Q_FCY = 0 stays invalid, so on
//   the files without Fcy (MF 5.2, PAC2002) the solve ended in the 80-step bisection.
// - Every type's start lands on Romega itself there (the free deflection is below Rl's spacing),
//   where an upright wheel's ρz is 0: the slope there is the compressed side's, else Newton saw a
//   flat Fz62, stepped to Rl = 0 and back (fixed point: 3–8 steps, 4e-9 m off; float and the
//   lanes: the bisection fallback on the MF 5.2 and PAC2002 files below 1e-3 N).
// Upright and without Fy: one or two steps, and Rl the double solve's to each type's resolution.
// (With γ = 0.03 the MF 6.2 sample's root lies 18 cm above Romega; fixed point is 1.2e-6 m off it,
// 0.1 mm before the camber deflection was written with γ cancelled (FixedPointKeepsASmallCambers-
// Deflection, below). With Fy = 200 N at these loads, Fcy's (ρz/R0)^Q_FCY2 makes float 4e-7 m off.
// Neither is the solver's.)
TEST(Mf62LoadedRadius, LightestLoadsNeedNoFallback) {
  const auto fixed = [](double v) { return Fixed64::from_double(v); };
  constexpr std::array<double, 4> kGamma{0.0, 0.0, 0.03, 0.03};
  constexpr std::array<double, 4> kFy{0.0, 200.0, 0.0, 200.0};
  for (const std::string& name : fz62_path_tyres()) {
    const MfParameters<double> p = load(name.c_str());
    const MfParameters<Fixed64> px = to_fixed_parameters(p);
    const MfParameters<float> pf = convert_parameters<float>(p);
    const double omega = 50.0;
    const double romega = romega_at(p, omega);
    for (const double fz : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0}) {
      lanes::F4 gamma4;
      lanes::F4 fy4;
      for (std::size_t k = 0; k < 4; ++k) {
        gamma4.v[k] = static_cast<float>(kGamma[k]);
        fy4.v[k] = static_cast<float>(kFy[k]);
      }
      const auto solved4 = detail::loaded_radius62(
          detail::fz62_curve(pf, gamma4, lanes::F4(static_cast<float>(omega)),
                             lanes::F4(static_cast<float>(romega)), lanes::F4(0.0F),
                             lanes::F4(0.0F), fy4),
          lanes::F4(static_cast<float>(fz)));
      const std::string at = name + " Fz " + std::to_string(fz) + " N";
      EXPECT_FALSE(solved4.fallback) << at << " (four lanes)";
      for (std::size_t k = 0; k < 4; ++k) {
        const double gamma = kGamma[k];
        const double fy = kFy[k];
        const auto reference =
            detail::loaded_radius62(detail::fz62_curve(p, gamma, omega, romega, 0.0, 0.0, fy), fz);
        const auto solvedx = detail::loaded_radius62(
            detail::fz62_curve(px, fixed(gamma), fixed(omega), fixed(romega), fixed(0.0),
                               fixed(0.0), fixed(fy)),
            fixed(fz));
        const auto solvedf = detail::loaded_radius62(
            detail::fz62_curve(pf, static_cast<float>(gamma), static_cast<float>(omega),
                               static_cast<float>(romega), 0.0F, 0.0F, static_cast<float>(fy)),
            static_cast<float>(fz));
        const std::string where =
            at + ", gamma " + std::to_string(gamma) + ", Fy " + std::to_string(fy);
        EXPECT_FALSE(reference.fallback) << where;
        EXPECT_FALSE(solvedx.fallback) << where << " (fixed point)";
        EXPECT_FALSE(solvedf.fallback) << where << " (float)";
        EXPECT_LE(solvedx.newton_steps, 11) << where;
        EXPECT_LE(solvedf.newton_steps, 11) << where;
        if (k == 0) {  // upright, no Fy
          EXPECT_LE(reference.newton_steps, 2) << where;
          EXPECT_LE(solvedx.newton_steps, 2) << where << " (fixed point)";
          EXPECT_LE(solvedf.newton_steps, 2) << where << " (float)";
          EXPECT_NEAR(solvedx.rl_m.to_double(), reference.rl_m, 1e-9) << where;
          EXPECT_NEAR(solvedf.rl_m, reference.rl_m, 6e-8) << where;
          EXPECT_NEAR(solved4.rl_m.v[0], reference.rl_m, 6e-8) << where;
          // ρz, the divisor of Cz = Fz/ρz: float's and the lanes' to their precision relative to
          // ρz (it had been Romega − Rl, in steps of Rl's rounding, 3e-8 m: 3–30 % off at 0.1 N,
          // and 0 below 0.006 N, where the start rounds onto Romega); fixed point's within two
          // Q31.32 steps.
          EXPECT_NEAR(solvedf.rho_m, reference.rho_m, 2e-6 * reference.rho_m) << where;
          EXPECT_NEAR(solved4.rho_m.v[0], reference.rho_m, 2e-6 * reference.rho_m) << where;
          EXPECT_NEAR(solvedx.rho_m.to_double(), reference.rho_m, 4.7e-10) << where;
        }
      }
      EXPECT_LE(solved4.newton_steps, 11) << at;
    }
  }
}

// A root within half of float's Rl step below Romega: Rl rounds onto Romega, but ρz is the
// deflection at the root, with its free-rolling part (it had been taken as lying at Romega: ρz
// without it, 25 % low on lanes at this point, found by a random sweep).
TEST(Mf62LoadedRadius, RootJustBelowRomegaKeepsItsFreeDeflection) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<float> pf = convert_parameters<float>(p);
  // The inputs as float has them (Romega's rounding alone, up to 1.5e-8 m, is a third of ρz).
  const auto as_float = [](double v) { return static_cast<float>(v); };
  const double gamma = as_float(1.3997835659163015e-6);
  const double omega = as_float(56.883249961080558);
  const double romega = as_float(0.39462820925241843);
  const double dpi = as_float(-0.32200814828518198);
  const double fz = as_float(0.0097450512196749182);
  const auto reference =
      detail::loaded_radius62(detail::fz62_curve(p, gamma, omega, romega, dpi, 0.0, 0.0), fz);
  const auto solvedf =
      detail::loaded_radius62(detail::fz62_curve(pf, as_float(gamma), as_float(omega),
                                                 as_float(romega), as_float(dpi), 0.0F, 0.0F),
                              as_float(fz));
  const auto solved4 = detail::loaded_radius62(
      detail::fz62_curve(pf, lanes::F4(as_float(gamma)), lanes::F4(as_float(omega)),
                         lanes::F4(as_float(romega)), lanes::F4(as_float(dpi)), lanes::F4(0.0F),
                         lanes::F4(0.0F)),
      lanes::F4(as_float(fz)));
  ASSERT_GT(reference.rho_m, 0.0);
  // The lanes (Halley's steps) converge onto the root from just below Romega.
  EXPECT_NEAR(solved4.rho_m.v[0], reference.rho_m, 1e-5 * reference.rho_m);
  // Float (Newton's steps) starts on Romega itself, where the slope is the upper side's, and
  // settles from below with Rl's error estimated at most ε·R0 (4.7e-8 m), so ρz is not to its own
  // precision (that would need another evaluation there): 3.6e-9 m off here. Asserted at twice
  // that, below the 1.2e-8 m of a ρz without its free part.
  EXPECT_NEAR(solvedf.rho_m, reference.rho_m, 7.2e-9);
}

// Light loads with a small camber, in fixed point, through evaluate as `tread mf eval --fixed`
// prints them. The camber deflection (rtw/8)·|tan γ|·(num/den)² had been computed as
// γ²·(rtw/8)·|tan γ| / den², whose numerator (1e-10 at γ = 0.00165 for the MF 6.2 sample) is
// below Q31.32's resolution (2.3e-10): it became 0, the wheel lost its camber deflection, and at
// Fz = 6 N, γ = 0.00165, p = 175 kPa Rl was 0.3942 m, ρz too small, with status ok (double: Romega,
// 0.3944 m, where the camber alone carries more than Fz; see NoRootAboveRomegaIsRomega). γ now
// cancels before anything is rounded.
TEST(Mf62LoadedRadius, FixedPointKeepsASmallCambersDeflection) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<Fixed64> px = to_fixed_parameters(p);
  double worst = 0.0;
  int above_romega = 0;
  for (const int mode : {111, 211}) {
    const MfOptions o = options_from_use_mode(mode).value;
    for (const double fz : {0.1, 1.0, 6.0, 20.0, 100.0, 500.0}) {
      for (const double gamma : {-0.09, -0.01, -0.00165, -3e-4, 3e-4, 0.00165, 0.01, 0.09}) {
        for (const double alpha : {0.0, 0.05}) {
          for (const double pressure : {175067.0, 260000.0}) {
            MfInput<double> in = at_load(fz, 0.0, alpha, gamma);
            in.p_pa = pressure;
            const MfOutput<double> want = evaluate(p, in, o);
            const MfOutput<Fixed64> got = evaluate(px, testing::to_fixed(in), o);
            const std::string where = "mode " + std::to_string(mode) + " Fz " + std::to_string(fz) +
                                      " gamma " + std::to_string(gamma) + " alpha " +
                                      std::to_string(alpha) + " p " + std::to_string(pressure);
            ASSERT_EQ(got.status, want.status) << where;
            // Within fixed point's own accuracy (README: 0.1 % of an output's peak, here 0.4 mm
            // of Rl); measured below 2e-5 m.
            EXPECT_NEAR(got.rl_m.to_double(), want.rl_m, 5e-5) << where;
            EXPECT_NEAR(got.rho_m.to_double(), want.rho_m, 5e-5) << where;
            worst = std::max(worst, std::fabs(got.rl_m.to_double() - want.rl_m));
            above_romega += want.rl_m > p.unloaded_radius_m ? 1 : 0;
          }
        }
      }
    }
  }
  std::printf("fixed point at light cambered loads: |Rl - double| <= %.1e m; %d roots above R0\n",
              worst, above_romega);
  EXPECT_GT(above_romega, 0);  // the case that was lost is among them
}

MfInput<float> to_float(const MfInput<double>& in) {
  return {static_cast<float>(in.fz_n),      static_cast<float>(in.kappa),
          static_cast<float>(in.alpha_rad), static_cast<float>(in.gamma_rad),
          static_cast<float>(in.vx_mps),    static_cast<float>(in.phit_1pm),
          static_cast<float>(in.p_pa)};
}

// Where the camber alone carries more than Fz at Romega and Fz62 only rises above it (light,
// cambered wheels: the MF 6.2 sample at 0.1–20 N; a 245/60 R16 MF-Tool file at 100 N and 0.02 rad),
// Fz62(Rl) = Fz has no root: Rl is Romega, where Fz62 comes nearest Fz, and ρz the camber's
// deflection there, (rtw/8)·|tan γ|, in every path. It had been the bracket's end, Romega + w
// (0.649 m for this 0.394 m tyre), under status ok.
TEST(Mf62LoadedRadius, NoRootAboveRomegaIsRomega) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<float> pf = convert_parameters<float>(p);
  const MfParameters<Fixed64> px = to_fixed_parameters(p);
  const MfOptions o = options_from_use_mode(111).value;
  int checked = 0;
  for (const double fz : {0.1, 1.0, 6.0, 20.0}) {
    for (const double gamma : {-0.01, 0.00165, 0.01}) {
      MfInput<double> in = at_load(fz, 0.0, 0.0, gamma);
      in.p_pa = 260000.0;
      const MfOutput<double> d = evaluate(p, in, o);
      const double romega = romega_at(p, d.omega_radps);
      const double dpi = (d.p_pa - p.nompres_pa) / p.nompres_pa;
      const auto fz62 = [&](double rl) {
        return fz62_reference(p, d.gamma_rad, d.omega_radps, dpi, d.fx_n, d.fy_n, rl);
      };
      // Only the points without a root on either side of Romega.
      if (!(fz62(romega) > fz) || !(fz62(romega + p.width_m) > fz)) continue;
      bool rising = true;
      for (double rl = romega; rl < romega + p.width_m; rl += 1e-3) {
        rising = rising && fz62(rl + 1e-3) >= fz62(rl);
      }
      ASSERT_TRUE(rising) << "Fz " << fz << " gamma " << gamma;
      const std::string where = "Fz " + std::to_string(fz) + " gamma " + std::to_string(gamma);
      const double rtw = (1.075 - 0.5 * p.aspect_ratio) * p.width_m;
      const double rho_camber = rtw / 8.0 * std::fabs(std::tan(d.gamma_rad));
      EXPECT_NEAR(d.rl_m, romega, 1e-12) << where;
      EXPECT_NEAR(d.rho_m, rho_camber, 1e-9 * rho_camber + 1e-15) << where;
      const MfOutput<float> f = evaluate(pf, to_float(in), o);
      EXPECT_NEAR(f.rl_m, romega, 1e-6) << where;
      EXPECT_NEAR(f.rho_m, rho_camber, 1e-3 * rho_camber) << where;
      const MfOutput<Fixed64> x = evaluate(px, testing::to_fixed(in), o);
      EXPECT_NEAR(x.rl_m.to_double(), romega, 5e-5) << where;
      std::array<MfInput<float>, 4> four_in{};
      four_in.fill(to_float(in));
      std::array<MfOutput<float>, 4> four{};
      evaluate_four(pf, four_in, o, std::array<MountedSide, 4>{}, four);
      EXPECT_NEAR(four[0].rl_m, romega, 1e-6) << where;
      EXPECT_NEAR(four[0].rho_m, rho_camber, 1e-3 * rho_camber) << where;
      ++checked;
    }
  }
  EXPECT_GE(checked, 6);
}

// A file with PFZ1 > 1 at a low pressure: MF 6.2 sample file with PFZ1 = 1.5, pressures down to
// 5 % of NOMPRES (1 + PFZ1·dpi down to −0.425).
TEST(Mf62LoadedRadius, PressureFactorAtOrBelowZero) {
  MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  ASSERT_EQ(p.fit_type, FitType::mf62);
  p.pfz1 = 1.5;
  const BoundScan scan = scan_bound(p, {0.05, 0.2, 1.0 / 3.0, 0.3, 0.6});  // × NOMPRES
  // The test reaches the region: a pressure factor ≤ 0, and there Fz62(Romega) > Fz.
  EXPECT_GT(scan.factor_not_positive, 100);
  EXPECT_GT(scan.beyond_romega, 10);
  std::printf(
      "1 + PFZ1·dpi <= 0 at %d points: the root above Romega at %d, the hump below Romega "
      "missed (Rl = 0) at %d; |Rl - reference| float %.1e m\n",
      scan.factor_not_positive, scan.beyond_romega, scan.hump_missed, scan.worst_float);

  const MfParameters<float> pf = convert_parameters<float>(p);
  const MfOptions o = options_from_use_mode(211).value;
  // Four lanes: a wheel whose pressure factor is ≤ 0 beside wheels where it is positive; each
  // wheel's Rl is what it gets alone (its block filled with copies of it), bit for bit.
  for (const double fz : {100.0, 1000.0, 3000.0, p.fnomin_n, 2 * p.fnomin_n, p.fzmax_n}) {
    for (const double gamma : {-0.5, 0.1, 1.0}) {
      std::array<MfInput<float>, 4> mixed;
      for (std::size_t k = 0; k < 4; ++k) {
        mixed[k] = input_at<float>(p, {fz, 0.05, 0.2, gamma, 16.7, k % 2 == 0 ? 0.05 : 1.0});
      }
      const std::array<MountedSide, 4> sides{};
      std::array<MfOutput<float>, 4> together;
      evaluate_four(pf, mixed, o, sides, together);
      for (std::size_t k = 0; k < 4; ++k) {
        std::array<MfInput<float>, 4> same;
        same.fill(mixed[k]);
        std::array<MfOutput<float>, 4> alone;
        evaluate_four(pf, same, o, sides, alone);
        EXPECT_EQ(together[k].rl_m, alone[0].rl_m) << "Fz " << fz << " gamma " << gamma << ' ' << k;
        EXPECT_NEAR(together[k].rl_m, evaluate(pf, mixed[k], o).rl_m, 2e-5);
      }
    }
  }
}

}  // namespace
}  // namespace tread::mf
