// Unit tests of src/mf/mf_evaluate.hpp: properties that hold independently of MFeval's numbers.
#include "mf/mf_evaluate.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_options.hpp"

namespace tread::mf {
namespace {

MfInput<double> make_input(double fz, double kappa, double alpha, double gamma, double vx = 16.7) {
  MfInput<double> in;
  in.fz_n = fz;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.gamma_rad = gamma;
  in.vx_mps = vx;
  return in;
}

TEST(MfOptions, UseModeDigits) {
  const auto m111 = options_from_use_mode(111);
  ASSERT_TRUE(m111.ok());
  EXPECT_TRUE(m111.value.use_limits);
  EXPECT_FALSE(m111.value.use_alpha_star);
  EXPECT_FALSE(m111.value.use_turn_slip);
  const auto m222 = options_from_use_mode(222);
  ASSERT_TRUE(m222.ok());
  EXPECT_FALSE(m222.value.use_limits);
  EXPECT_TRUE(m222.value.use_alpha_star);
  EXPECT_TRUE(m222.value.use_turn_slip);
  for (int bad : {0, 11, 110, 113, 131, 311, 1111, -111}) {
    EXPECT_EQ(options_from_use_mode(bad).status, Status::invalid_argument) << bad;
  }
}

TEST(MfEvaluate, DefaultParametersAreTheBookTyre) {
  const MfParameters<double> p;
  EXPECT_DOUBLE_EQ(p.fnomin_n, 4000.0);
  EXPECT_DOUBLE_EQ(p.unloaded_radius_m, 0.3135);
  EXPECT_DOUBLE_EQ(p.pky1, -15.0);
  EXPECT_GT(kMfParameterCount, 200);
}

TEST(MfEvaluate, ZeroOrNegativeLoadGivesNoForces) {
  const MfParameters<double> p;
  for (int mode : {111, 121, 112, 211, 222}) {
    const MfOptions o = options_from_use_mode(mode).value;
    for (double fz : {0.0, -500.0}) {
      const MfOutput<double> out = evaluate(p, make_input(fz, 0.1, 0.1, 0.05), o);
      EXPECT_EQ(out.fx_n, 0.0) << mode;
      EXPECT_EQ(out.fy_n, 0.0) << mode;
      EXPECT_EQ(out.fz_n, 0.0) << mode;
      EXPECT_EQ(out.mx_nm, 0.0) << mode;
      EXPECT_EQ(out.my_nm, 0.0) << mode;
      EXPECT_EQ(out.mz_nm, 0.0) << mode;
    }
  }
}

// The rolling resistance moment resists the wheel's rotation: My < 0 while the wheel turns
// forward (κ > −1 at Vx > 0), > 0 once it spins backward (κ < −1), faded to 0 across the band
// κ = −1 ± VXLOW/|Vx| and continuous there, whatever VXLOW. MFeval's lower band end,
// −1 − VXLOW − (VXLOW/|Vx| − 1), is that only at VXLOW = 1 m/s: at 0.1 m/s My drove the wheel
// under braking beyond κ ≈ −0.1 (+17.8 N m at κ = −0.3, 16.7 m/s).
TEST(MfEvaluate, RollingResistanceMomentResistsTheRotationAtAnyVxlow) {
  for (const double vxlow : {0.1, 0.5, 1.0, 3.0}) {
    MfParameters<double> p;
    p.vxlow_mps = vxlow;
    p.kpumin = -1.9;
    const MfOptions o = options_from_use_mode(111).value;
    for (const double vx : {5.0, 16.7, 30.0}) {
      const double band = vxlow / vx;
      for (const double kappa : {-0.9, -0.5, -0.3, -0.1, 0.0, 0.1}) {
        if (kappa <= -1.0 + band) continue;
        EXPECT_LT(evaluate(p, make_input(4000.0, kappa, 0.0, 0.0, vx), o).my_nm, 0.0)
            << "VXLOW " << vxlow << ", Vx " << vx << ", κ " << kappa;
        MfInput<float> in;
        in.fz_n = 4000.0f;
        in.kappa = static_cast<float>(kappa);
        in.vx_mps = static_cast<float>(vx);
        EXPECT_LT(evaluate(convert_parameters<float>(p), in, o).my_nm, 0.0f);
      }
      const double behind = -1.0 - band - 0.05;
      EXPECT_GT(evaluate(p, make_input(4000.0, behind, 0.0, 0.0, vx), o).my_nm, 0.0)
          << "VXLOW " << vxlow << ", Vx " << vx;
      // Continuous where the band ends below: the faded value meets the reversed one.
      const double end = -1.0 - band;
      const double below = evaluate(p, make_input(4000.0, end - 1e-9, 0.0, 0.0, vx), o).my_nm;
      const double inside = evaluate(p, make_input(4000.0, end + 1e-9, 0.0, 0.0, vx), o).my_nm;
      EXPECT_NEAR(below, inside, 1e-6 * std::fabs(below)) << "VXLOW " << vxlow << ", Vx " << vx;
    }
  }
}

TEST(MfEvaluate, PureSlipShape) {
  // Book tyre, no shifts: Fx(κ) odd, Fx'(0) = Kxk, Fy'(0) = Kya (mode 211: no low-speed effects).
  const MfParameters<double> p;
  const MfOptions o = options_from_use_mode(211).value;
  const double h = 1e-7;
  const MfOutput<double> at0 = evaluate(p, make_input(4000.0, 0.0, 0.0, 0.0), o);
  const double fx_p = evaluate(p, make_input(4000.0, h, 0.0, 0.0), o).fx_n;
  const double fx_m = evaluate(p, make_input(4000.0, -h, 0.0, 0.0), o).fx_n;
  EXPECT_NEAR(fx_p, -fx_m, 1e-9);
  EXPECT_NEAR((fx_p - fx_m) / (2 * h), at0.kxk_n, 1e-4 * at0.kxk_n);
  // Kxk = Fz·PKX1 at the nominal load (PKX2 = PKX3 = 0 in the book file).
  EXPECT_NEAR(at0.kxk_n, 4000.0 * 16.0, 1e-9);
  const double fy_p = evaluate(p, make_input(4000.0, 0.0, h, 0.0), o).fy_n;
  const double fy_m = evaluate(p, make_input(4000.0, 0.0, -h, 0.0), o).fy_n;
  EXPECT_NEAR((fy_p - fy_m) / (2 * h), at0.kya_nprad, 1e-4 * std::fabs(at0.kya_nprad));
  // Kya = PKY1·Fz0·sin(PKY4·atan(1/PKY2)) at Fz = Fz0.
  EXPECT_NEAR(at0.kya_nprad, -15.0 * 4000.0 * std::sin(2.0 * std::atan(0.5)), 1e-6);
  // Peak: |Fx| ≤ Dx = mux·Fz with mux = PDX1 at Fz0.
  double peak = 0.0;
  for (double k = 0.0; k < 1.0; k += 0.001) {
    peak = std::max(peak, std::fabs(evaluate(p, make_input(4000.0, k, 0.0, 0.0), o).fx_n));
  }
  EXPECT_NEAR(peak, 1.0 * 4000.0, 1.0);
}

TEST(MfEvaluate, CombinedSlipReducesEachForce) {
  const MfParameters<double> p;
  const MfOptions o = options_from_use_mode(211).value;
  // Adding the other slip shrinks each force (friction ellipse).
  const auto pure_x = evaluate(p, make_input(4000.0, 0.08, 0.0, 0.0), o);
  const auto comb_x = evaluate(p, make_input(4000.0, 0.08, 0.1, 0.0), o);
  EXPECT_LT(std::fabs(comb_x.fx_n), std::fabs(pure_x.fx_n));  // friction ellipse
  const auto pure_y = evaluate(p, make_input(4000.0, 0.0, 0.1, 0.0), o);
  const auto comb_y = evaluate(p, make_input(4000.0, 0.08, 0.1, 0.0), o);
  EXPECT_LT(std::fabs(comb_y.fy_n), std::fabs(pure_y.fy_n));
}

TEST(MfEvaluate, UncombinedIgnoresTheOtherSlip) {
  MfParameters<double> p;
  p.rhx1 = 0.01;  // so combined and pure differ even at zero other slip
  MfOptions pure = options_from_use_mode(211).value;
  pure.combined = false;
  const MfOptions combined = options_from_use_mode(211).value;
  const auto a = evaluate(p, make_input(4000.0, 0.07, 0.0, 0.02), pure);
  const auto b = evaluate(p, make_input(4000.0, 0.07, 0.15, 0.02), pure);
  EXPECT_DOUBLE_EQ(a.fx_n, b.fx_n);  // Fx0 does not depend on α
  const auto c = evaluate(p, make_input(4000.0, 0.0, 0.1, 0.02), pure);
  const auto d = evaluate(p, make_input(4000.0, 0.2, 0.1, 0.02), pure);
  EXPECT_DOUBLE_EQ(c.fy_n, d.fy_n);  // Fy0 does not depend on κ
  EXPECT_DOUBLE_EQ(c.mz_nm, d.mz_nm);
  // At κ = 0 the combined Fy is Fy0 (Gyk = 1, SVyk = 0 for the book tyre).
  EXPECT_NEAR(evaluate(p, make_input(4000.0, 0.0, 0.1, 0.02), combined).fy_n, c.fy_n, 1e-9);
  EXPECT_LT(std::fabs(evaluate(p, make_input(4000.0, 0.07, 0.15, 0.02), combined).fx_n),
            std::fabs(b.fx_n));
}

TEST(MfEvaluate, TyreSideMirroring) {
  MfParameters<double> left;
  left.tyre_side = TyreSide::left;
  // Asymmetric coefficients, so mirroring is visible.
  left.phy1 = 0.01;
  left.pvy1 = 0.03;
  left.qsx1 = 0.02;
  left.qhz1 = 0.01;
  MfParameters<double> right = left;
  right.tyre_side = TyreSide::right;
  for (int mode : {111, 121, 112, 211}) {
    MfOptions o = options_from_use_mode(mode).value;
    for (double alpha : {-0.1, 0.03, 0.2}) {
      for (double gamma : {-0.04, 0.0, 0.05}) {
        MfInput<double> in = make_input(4500.0, 0.05, alpha, gamma);
        in.phit_1pm = 0.02;
        MfInput<double> mirrored = in;
        mirrored.alpha_rad = -alpha;
        mirrored.gamma_rad = -gamma;
        mirrored.phit_1pm = -in.phit_1pm;

        o.side = MountedSide::as_measured;
        const auto base = evaluate(left, mirrored, o);
        // A left tyre on the right wheel = mirror image of the left tyre.
        o.side = MountedSide::right;
        const auto on_right = evaluate(left, in, o);
        EXPECT_DOUBLE_EQ(on_right.fx_n, base.fx_n);
        EXPECT_DOUBLE_EQ(on_right.fy_n, -base.fy_n);
        EXPECT_DOUBLE_EQ(on_right.mx_nm, -base.mx_nm);
        EXPECT_DOUBLE_EQ(on_right.my_nm, base.my_nm);
        EXPECT_DOUBLE_EQ(on_right.mz_nm, -base.mz_nm);
        EXPECT_DOUBLE_EQ(on_right.alpha_rad, in.alpha_rad);
        // Same side as the file: no mirroring, for either side.
        o.side = MountedSide::left;
        const auto left_on_left = evaluate(left, in, o);
        o.side = MountedSide::as_measured;
        const auto left_as_measured = evaluate(left, in, o);
        EXPECT_DOUBLE_EQ(left_on_left.fy_n, left_as_measured.fy_n);
        o.side = MountedSide::right;
        const auto right_on_right = evaluate(right, in, o);
        EXPECT_DOUBLE_EQ(right_on_right.fy_n, left_as_measured.fy_n);
        EXPECT_DOUBLE_EQ(right_on_right.mz_nm, left_as_measured.mz_nm);
        // A right tyre on the left wheel mirrors too.
        o.side = MountedSide::left;
        const auto right_on_left = evaluate(right, in, o);
        EXPECT_DOUBLE_EQ(right_on_left.fy_n, on_right.fy_n);
        EXPECT_DOUBLE_EQ(right_on_left.mz_nm, on_right.mz_nm);
        // The asymmetry is real: the mirror image differs from the tyre itself.
        if (alpha > 0.1 && gamma > 0.0) {
          EXPECT_NE(on_right.fy_n, left_as_measured.fy_n);
        }
      }
    }
  }
}

TEST(MfEvaluate, EnvelopeFlagsAbsurdInputs) {
  const MfParameters<double> p;
  const MfOptions o = options_from_use_mode(211).value;
  EXPECT_EQ(evaluate(p, make_input(4000.0, 0.1, 0.1, 0.0), o).status, Status::ok);
  EXPECT_EQ(evaluate(p, make_input(1e9, 0.1, 0.1, 0.0), o).status, Status::out_of_range);
  EXPECT_EQ(evaluate(p, make_input(4000.0, 1e6, 0.1, 0.0), o).status, Status::out_of_range);
  EXPECT_EQ(evaluate(p, make_input(4000.0, 0.1, 0.1, 0.0, 1e5), o).status, Status::out_of_range);
}

TEST(MfEvaluate, LoadedRadiusOnlyExtrasGiveTheSameRadiiAndSkipTheRest) {
  // MfOptions::extras_loaded_radius_only (the node's Rl): forces, moments, Re, Rl, rho and Cz as
  // with all extras, bit for bit (float and double); contact patch and relaxation lengths 0.
  const auto check = [](auto scalar) {
    using T = decltype(scalar);
    for (const FitType fit : {FitType::mf61, FitType::mf62, FitType::mf52}) {
      MfParameters<T> p;
      p.fit_type = fit;
      MfOptions all;
      MfOptions rl_only;
      rl_only.extras_loaded_radius_only = true;
      MfInput<T> in;
      in.fz_n = T(4200);
      in.kappa = T(0.05);
      in.alpha_rad = T(-0.04);
      in.gamma_rad = T(0.02);
      in.vx_mps = T(16.7);
      const MfOutput<T> a = evaluate(p, in, all);
      const MfOutput<T> b = evaluate(p, in, rl_only);
      EXPECT_EQ(a.fx_n, b.fx_n);
      EXPECT_EQ(a.fy_n, b.fy_n);
      EXPECT_EQ(a.mz_nm, b.mz_nm);
      EXPECT_EQ(a.mx_nm, b.mx_nm);
      EXPECT_EQ(a.my_nm, b.my_nm);
      EXPECT_EQ(a.re_m, b.re_m);
      EXPECT_EQ(a.rl_m, b.rl_m);
      EXPECT_EQ(a.rho_m, b.rho_m);
      EXPECT_EQ(a.cz_npm, b.cz_npm);
      EXPECT_GT(a.rl_m, T(0.25));
      EXPECT_GT(a.contact_length_m, T(0));
      EXPECT_GT(a.cx_npm, T(0));
      EXPECT_EQ(b.contact_length_m, T(0));
      EXPECT_EQ(b.contact_width_m, T(0));
      EXPECT_EQ(b.cx_npm, T(0));
      EXPECT_EQ(b.sigmax_m, T(0));
      EXPECT_EQ(b.sigmay_m, T(0));
    }
  };
  check(0.0);
  check(0.0f);
}

TEST(MfEvaluate, FloatFollowsDouble) {
  const MfParameters<double> pd;
  const MfParameters<float> pf = convert_parameters<float>(pd);
  const MfOptions o = options_from_use_mode(111).value;
  MfInput<float> inf;
  inf.fz_n = 3000.0f;
  inf.kappa = 0.05f;
  inf.alpha_rad = 0.05f;
  inf.vx_mps = 20.0f;
  const auto of = evaluate(pf, inf, o);
  const auto od = evaluate(pd, make_input(3000.0, 0.05, 0.05, 0.0, 20.0), o);
  EXPECT_NEAR(static_cast<double>(of.fx_n), od.fx_n, 1e-4 * 3000.0);
  EXPECT_NEAR(static_cast<double>(of.fy_n), od.fy_n, 1e-4 * 3000.0);
  EXPECT_NEAR(static_cast<double>(of.mz_nm), od.mz_nm, 1e-3);
}

// calculateRe in float starts at the map's fixed point (a series in ε = B/A³, where |ε| < 0.02
// and A > R0/2) instead of at MFeval's 0.965·R0, so that its first step is its last; double keeps
// MFeval's iterates. Float must take one step wherever the series is taken, and land on double's
// fixed point within its start's error and float's rounding (see the tolerances below). The grid:
// ε from about −0.1 to 0.1 (Q_V1 of both signs; both sides of |ε| = 0.02), a locked (κ = −1:
// ω = 0), reversed (κ = −1.5) and standing wheel. (A > R0/2 holds on the whole grid: A is R0·Q_RE0
// less a deflection of a few cm; the branch A ≤ R0/2, absurd loads, is not exercised.)
TEST(MfEvaluate, FloatRollingRadiusStartsAtItsFixedPoint) {
  const MfOptions o = options_from_use_mode(111).value;
  int compared = 0;
  int series = 0;
  int beyond_above = 0;
  int beyond_below = 0;
  for (const double q_v1 : {6.2e-4, -6.2e-4, 4e-3, -4e-3}) {
    MfParameters<double> pd;
    pd.q_v1 = q_v1;
    const MfParameters<float> pf = convert_parameters<float>(pd);
    for (const double fz : {0.0, 1000.0, 4000.0, 16000.0}) {
      for (const double vx : {-30.0, -1.0, 0.0, 0.5, 16.7, 40.0}) {
        for (const double kappa : {-1.5, -1.0, -0.3, 0.0, 0.4, 1.0}) {
          const auto od = evaluate(pd, make_input(fz, kappa, 0.0, 0.0, vx), o);
          MfInput<float> in;
          in.fz_n = static_cast<float>(fz);
          in.kappa = static_cast<float>(kappa);
          in.vx_mps = static_cast<float>(vx);
          const auto of = evaluate(pf, in, o);
          SCOPED_TRACE("Q_V1 " + std::to_string(q_v1) + " Fz " + std::to_string(fz) + " Vx " +
                       std::to_string(vx) + " κ " + std::to_string(kappa));
          ASSERT_TRUE(std::isfinite(od.re_m));
          // ε from double's fixed point Re = A + B/Re².
          const double speed = (kappa * vx + vx) * pd.unloaded_radius_m / pd.longvl_mps;
          const double b = pd.unloaded_radius_m * q_v1 * speed * speed;
          const double a = od.re_m - b / (od.re_m * od.re_m);
          const double eps = b / (a * a * a);
          ASSERT_GT(a, 0.5 * pd.unloaded_radius_m);
          detail::Prepared<float> prepared = detail::prepare(pf, in, o);
          const int steps = detail::rolling_radius(pf, prepared);
          // From the series: ω is taken at the start (within 143·|ε|⁵·A of the fixed point), Re one
          // step on (that error times 2ε), both to float's rounding (5 ulp of Re here; 1.9 seen on
          // x86-64). From 0.965·R0 (|ε| > 0.02): MFeval's stop, a last step below 1e-6 m; ω is the
          // step before the last's.
          double re_tolerance = 5e-7;
          double omega_tolerance = 5e-6;
          if (std::fabs(eps) < 0.019) {
            EXPECT_EQ(steps, 1) << "ε " << eps;
            re_tolerance = 1.5e-7;
            omega_tolerance = 1e-6;
            ++series;
          } else if (eps > 0.021) {
            EXPECT_GT(steps, 1) << "ε " << eps;
            ++beyond_above;
          } else if (eps < -0.021) {
            EXPECT_GT(steps, 1) << "ε " << eps;
            ++beyond_below;
          }
          EXPECT_NEAR(static_cast<double>(of.re_m), od.re_m, re_tolerance) << "ε " << eps;
          EXPECT_NEAR(static_cast<double>(of.omega_radps), od.omega_radps,
                      omega_tolerance * std::fabs(od.omega_radps) + 1e-6)
              << "ε " << eps;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 4 * 4 * 6 * 6);
  EXPECT_GT(series, 0);
  EXPECT_GT(beyond_above, 0);
  EXPECT_GT(beyond_below, 0);
}

// The same on four lanes, some of a group from the series and some not: each lane's Re and ω are
// double's within float's tolerance, whatever its neighbours take.
TEST(MfEvaluate, FourLanesRollingRadiusMixesStartsPerLane) {
  const MfOptions o = options_from_use_mode(111).value;
  MfParameters<double> pd;
  pd.q_v1 = 4e-3;
  const MfParameters<float> pf = convert_parameters<float>(pd);
  // ε ≈ 0.0004, 0.095 (beyond the series: from 0.965·R0), 0 (standing), 0.006.
  const std::array<std::array<double, 3>, 4> points{
      {{4000.0, 0.0, 5.0}, {4000.0, 1.0, 40.0}, {2000.0, 0.3, 0.0}, {8000.0, 0.0, 17.0}}};
  std::array<MfInput<float>, 4> four{};
  for (std::size_t k = 0; k < 4; ++k) {
    four[k].fz_n = static_cast<float>(points[k][0]);
    four[k].kappa = static_cast<float>(points[k][1]);
    four[k].vx_mps = static_cast<float>(points[k][2]);
  }
  std::array<MfOutput<float>, 4> out{};
  evaluate_four(pf, four, o,
                {MountedSide::left, MountedSide::left, MountedSide::left, MountedSide::left}, out);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto od = evaluate(pd, make_input(points[k][0], points[k][1], 0.0, 0.0, points[k][2]), o);
    SCOPED_TRACE("lane " + std::to_string(k));
    // As the scalar test's (lane 1 is beyond the series, from 0.965·R0).
    const bool from_series = k != 1;
    EXPECT_NEAR(static_cast<double>(out[k].re_m), od.re_m, from_series ? 1.5e-7 : 5e-7);
    EXPECT_NEAR(static_cast<double>(out[k].omega_radps), od.omega_radps,
                (from_series ? 1e-6 : 5e-6) * std::fabs(od.omega_radps) + 1e-6);
  }
}

}  // namespace
}  // namespace tread::mf
