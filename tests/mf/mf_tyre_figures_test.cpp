// tyre_figures (sim/tyre/mf_tyre_figures.hpp) against MFeval's own stiffness outputs and against
// the curves it summarises.
#include <gtest/gtest.h>

#include <cmath>

#include "csv_table.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "tyre/mf_tyre_figures.hpp"

namespace tread::mf {
namespace {

TEST(MfTyreFigures, StiffnessesMatchMfeval) {
  const MfParameters<double> p =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params;
  const testing::CsvTable ref = testing::read_csv(
      testing::test_data("mfeval/mfeval_MagicFormula61_Parameters_mode111.csv").string());
  int compared = 0;
  for (std::size_t r = 0; r < ref.rows.size(); ++r) {
    if (std::fabs(ref.at(r, "in_kappa_1")) > 1e-12 ||
        std::fabs(ref.at(r, "in_alpha_rad")) > 1e-12 ||
        std::fabs(ref.at(r, "in_gamma_rad")) > 1e-12) {
      continue;
    }
    const tyre::MfTyreFigures f =
        tyre::tyre_figures(p, MfOptions{}, ref.at(r, "in_Fz_N"), ref.at(r, "in_Vx_mps"));
    EXPECT_TRUE(f.finite);
    EXPECT_NEAR(f.kya_nprad, -ref.at(r, "Kya_Nprad"), 1e-5 * std::fabs(ref.at(r, "Kya_Nprad")));
    EXPECT_NEAR(f.kxk_n, ref.at(r, "Kxk_N"), 1e-5 * std::fabs(ref.at(r, "Kxk_N")));
    EXPECT_NEAR(f.re_m, ref.at(r, "Re_m"), 1e-6);
    ++compared;
  }
  EXPECT_EQ(compared, 3);  // Fz = 2, 4, 6 kN
}

TEST(MfTyreFigures, PeaksAreThePeaksOfTheCurves) {
  const MfParameters<double> p =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params;
  const tyre::MfTyreFigures f = tyre::tyre_figures(p, MfOptions{});
  EXPECT_DOUBLE_EQ(f.fz_n, p.fnomin_n);
  EXPECT_DOUBLE_EQ(f.p_pa, p.inflpres_pa);
  // No point of a fine sweep beats the reported peak by more than the grid's resolution.
  MfInput<double> in;
  in.fz_n = f.fz_n;
  in.vx_mps = f.vx_mps;
  double best_drive = 0.0;
  double best_lateral = 0.0;
  for (int i = 1; i <= 4000; ++i) {
    in.kappa = static_cast<double>(i) / 4000.0;
    in.alpha_rad = 0.0;
    best_drive = std::max(best_drive, evaluate(p, in, MfOptions{}).fx_n / f.fz_n);
    in.kappa = 0.0;
    in.alpha_rad = 0.5 * static_cast<double>(i - 2000) / 2000.0;
    best_lateral = std::max(best_lateral, std::fabs(evaluate(p, in, MfOptions{}).fy_n) / f.fz_n);
  }
  EXPECT_NEAR(f.mux_drive, best_drive, 1e-4);
  EXPECT_LE(f.mux_drive, best_drive + 1e-12);
  EXPECT_NEAR(f.muy, best_lateral, 1e-4);
  EXPECT_GT(f.mux_drive, 1.0);
  EXPECT_GT(f.mux_brake, 1.0);
  EXPECT_GT(f.kappa_drive, 0.0);
  EXPECT_LT(f.kappa_brake, 0.0);
  EXPECT_GT(f.kya_nprad, 0.0);  // a normal tyre: Fy < 0 for α > 0 in ISO-W
  EXPECT_GT(f.kxk_n, 0.0);
  EXPECT_GT(f.trail_m, 0.0);
  EXPECT_LT(f.trail_m, 0.1);
}

// A tyre whose range ends before its peaks (the FEDA file: ALPMIN −0.195 rad, KPUMAX 0): the
// peaks are searched within the range, a peak at its end says so, and no drive peak is made up
// where the file allows no drive slip. Without the limits (useMode 2xx) the whole grid counts.
TEST(MfTyreFigures, PeaksStayInsideTheTyresRange) {
  const MfParameters<double> p =
      tyre::load_mf_parameters(testing::tyre_file("chrono_feda_335_65R22_5_G275MSA_60psi.tir"))
          .params;
  ASSERT_GT(p.alpmin_rad, -0.5);
  ASSERT_LE(p.kpumax, 0.0);
  const tyre::MfTyreFigures f = tyre::tyre_figures(p, MfOptions{});
  EXPECT_GE(f.alpha_muy_rad, p.alpmin_rad);
  EXPECT_LE(f.alpha_muy_rad, p.alpmax_rad);
  EXPECT_TRUE(f.alpha_muy_at_limit);  // this tyre's |Fy| still rises at ALPMIN
  EXPECT_DOUBLE_EQ(f.alpha_muy_rad, p.alpmin_rad);
  EXPECT_FALSE(f.drive_in_range);
  EXPECT_TRUE(f.brake_in_range);
  EXPECT_GE(f.kappa_brake, p.kpumin);
  MfOptions no_limits;
  no_limits.use_limits = false;
  const tyre::MfTyreFigures g = tyre::tyre_figures(p, no_limits);
  EXPECT_TRUE(g.drive_in_range);
  EXPECT_FALSE(g.alpha_muy_at_limit);
  EXPECT_GE(g.muy, f.muy);
}

}  // namespace
}  // namespace tread::mf
