// PAC2002 (Adams, steady state, ζ = 1) on the MF 5.2 path of src/mf:
//  - on the Chrono PAC2002 file with FITTYP = 6 added, FitType::pac2002 agrees with FitType::mf52
//    (MFeval's path, checked against MFeval by mf_golden_test) on a combined-slip grid;
//  - the original Chrono file (no FITTYP) loads as pac2002 and gives the same results;
//  - pure-slip Fx0 and Fy0 equal the PAC2002 equations written out here independently
//    (Adams PAC2002 documentation / seed eq. 115–159 with ζ = 1), for several loads and cambers;
//  - the camber scale factors act: Fy(γ; LGAY = ½) = Fy(γ/2; LGAY = 1) in pure side slip.
#include <gtest/gtest.h>

#include <cmath>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf_output_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

MfParameters<double> load(const char* name) {
  const auto path = testing::tyre_file(name);
  EXPECT_TRUE(std::filesystem::exists(path)) << path;
  return tyre::load_mf_parameters(path).params;
}

MfInput<double> input(double fz, double kappa, double alpha, double gamma) {
  MfInput<double> in;
  in.fz_n = fz;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.gamma_rad = gamma;
  in.vx_mps = 16.7;
  return in;
}

int sgn(double x) {
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

/// PAC2002 pure longitudinal force (Adams PAC2002 documentation, ζ = 1, no pressure terms).
double pac2002_fx0(const MfParameters<double>& p, double fz, double kappa, double gamma) {
  const double fz0 = p.fnomin_n * p.lfzo;
  const double dfz = (fz - fz0) / fz0;
  const double gx = gamma * p.lgax;
  const double cx = p.pcx1 * p.lcx;
  const double mux = (p.pdx1 + p.pdx2 * dfz) * (1 - p.pdx3 * gx * gx) * p.lmux;
  const double dx = mux * fz;
  const double kx = fz * (p.pkx1 + p.pkx2 * dfz) * std::exp(p.pkx3 * dfz) * p.lkx;
  const double bx = kx / (cx * dx);
  const double shx = (p.phx1 + p.phx2 * dfz) * p.lhx;
  const double svx = fz * (p.pvx1 + p.pvx2 * dfz) * p.lvx * p.lmux;
  const double kx_s = kappa + shx;
  const double ex = (p.pex1 + p.pex2 * dfz + p.pex3 * dfz * dfz) * (1 - p.pex4 * sgn(kx_s)) * p.lex;
  return dx * std::sin(cx * std::atan(bx * kx_s - ex * (bx * kx_s - std::atan(bx * kx_s)))) + svx;
}

/// PAC2002 pure lateral force.
double pac2002_fy0(const MfParameters<double>& p, double fz, double alpha, double gamma) {
  const double fz0 = p.fnomin_n;
  const double dfz = (fz - fz0 * p.lfzo) / (fz0 * p.lfzo);
  const double gy = gamma * p.lgay;
  const double cy = p.pcy1 * p.lcy;
  const double muy = (p.pdy1 + p.pdy2 * dfz) * (1 - p.pdy3 * gy * gy) * p.lmuy;
  const double dy = muy * fz;
  const double ky = p.pky1 * fz0 * std::sin(2 * std::atan(fz / (p.pky2 * fz0 * p.lfzo))) *
                    (1 - p.pky3 * std::fabs(gy)) * p.lfzo * p.lky;
  const double by = ky / (cy * dy);
  const double shy = (p.phy1 + p.phy2 * dfz) * p.lhy + p.phy3 * gy;
  const double svy = fz * ((p.pvy1 + p.pvy2 * dfz) * p.lvy + (p.pvy3 + p.pvy4 * dfz) * gy) * p.lmuy;
  const double ay = alpha + shy;
  const double ey = (p.pey1 + p.pey2 * dfz) * (1 - (p.pey3 + p.pey4 * gy) * sgn(ay)) * p.ley;
  return dy * std::sin(cy * std::atan(by * ay - ey * (by * ay - std::atan(by * ay)))) + svy;
}

TEST(MfPac2002, AgreesWithMf52PathOnTheFittyp6File) {
  const MfParameters<double> mf52 = load("derived_chrono_VW_mf_185_80R14_PAC2002_FITTYP6.tir");
  ASSERT_EQ(mf52.fit_type, FitType::mf52);
  MfParameters<double> pac = mf52;
  pac.fit_type = FitType::pac2002;
  const MfParameters<double> chrono = load("chrono_VW_mf_185_80R14_PAC2002.tir");
  ASSERT_EQ(chrono.fit_type, FitType::pac2002);
  const auto columns = testing::output_columns<double>();
  int compared = 0;
  for (int mode : {111, 121, 211}) {
    const MfOptions o = options_from_use_mode(mode).value;
    for (double fz : {1000.0, 3800.0, 7000.0}) {
      for (double kappa = -0.3; kappa <= 0.3001; kappa += 0.05) {
        for (double alpha = -0.2; alpha <= 0.2001; alpha += 0.05) {
          for (double gamma : {-0.05, 0.0, 0.05}) {
            const auto a = evaluate(mf52, input(fz, kappa, alpha, gamma), o);
            const auto b = evaluate(pac, input(fz, kappa, alpha, gamma), o);
            const auto c = evaluate(chrono, input(fz, kappa, alpha, gamma), o);
            for (const auto& col : columns) {
              const double va = a.*(col.member);
              EXPECT_NEAR(b.*(col.member), va, 1e-12 * std::max(1.0, std::fabs(va))) << col.name;
              EXPECT_NEAR(c.*(col.member), va, 1e-12 * std::max(1.0, std::fabs(va))) << col.name;
              ++compared;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(MfPac2002, PureSlipMatchesThePac2002Equations) {
  const MfParameters<double> p = load("chrono_VW_mf_185_80R14_PAC2002.tir");
  const MfOptions o = options_from_use_mode(211).value;  // no limits, no low-speed model, α* = α
  double worst = 0.0;
  for (double fz : {1500.0, 3800.0, 6000.0}) {
    for (double gamma : {-0.06, 0.0, 0.04}) {
      for (double s = -0.4; s <= 0.4001; s += 0.02) {
        const double fx = evaluate(p, input(fz, s, 0.0, gamma), o).fx_n;
        const double fx_ref = pac2002_fx0(p, fz, s, gamma);
        const double fy = evaluate(p, input(fz, 0.0, s, gamma), o).fy_n;
        const double fy_ref = pac2002_fy0(p, fz, s, gamma);
        EXPECT_NEAR(fx, fx_ref, 1e-8 * fz) << "Fz " << fz << " kappa " << s << " gamma " << gamma;
        EXPECT_NEAR(fy, fy_ref, 1e-8 * fz) << "Fz " << fz << " alpha " << s << " gamma " << gamma;
        worst = std::max({worst, std::fabs(fx - fx_ref) / fz, std::fabs(fy - fy_ref) / fz});
      }
    }
  }
  std::printf("[ pac2002  ] worst |tread − PAC2002 equations| / Fz = %.3g\n", worst);
}

TEST(MfPac2002, CamberScaleFactors) {
  MfParameters<double> p = load("chrono_VW_mf_185_80R14_PAC2002.tir");
  const MfOptions o = options_from_use_mode(211).value;
  MfParameters<double> half = p;
  half.lgay = 0.5;
  half.lgax = 0.5;
  for (double alpha : {-0.1, 0.02, 0.15}) {
    EXPECT_NEAR(evaluate(half, input(4000.0, 0.0, alpha, 0.08), o).fy_n,
                evaluate(p, input(4000.0, 0.0, alpha, 0.04), o).fy_n, 1e-9);
  }
  for (double kappa : {-0.1, 0.05}) {
    EXPECT_NEAR(evaluate(half, input(4000.0, kappa, 0.0, 0.08), o).fx_n,
                evaluate(p, input(4000.0, kappa, 0.0, 0.04), o).fx_n, 1e-9);
  }
  // MF 5.2 (MFeval) ignores them.
  MfParameters<double> mf52 = half;
  mf52.fit_type = FitType::mf52;
  MfParameters<double> mf52_one = p;
  mf52_one.fit_type = FitType::mf52;
  EXPECT_DOUBLE_EQ(evaluate(mf52, input(4000.0, 0.0, 0.1, 0.08), o).fy_n,
                   evaluate(mf52_one, input(4000.0, 0.0, 0.1, 0.08), o).fy_n);
}

}  // namespace
}  // namespace tread::mf
