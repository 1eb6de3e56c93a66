// Measurement files for `tread fit`: CSV with the column names `tread mf eval` accepts (also TTC
// names in SAE axes) and TYDEX (.tdx), with
// unit conversion and file:line errors. Small files written here.
#include "fit/measurement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tread::fit {
namespace {

std::string error_of(const std::string& text, bool tydex) {
  std::istringstream in(text);
  try {
    if (tydex) {
      read_tydex(in, "m.tdx");
    } else {
      read_measurement_csv(in, "m.csv");
    }
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(MeasurementCsv, ReadsColumnsInAnyOrderAndSubsets) {
  std::istringstream in(
      "# comment\n"
      "Fy_N,alpha_rad,kappa,Fz_N,Vx_mps,extra\n"
      "\n"
      "-100.5,0.01,0,4000,16.6,7\n"
      ",0.02,0,4000,16.6,7\n");
  const MeasurementSet set = read_measurement_csv(in, "m.csv");
  ASSERT_EQ(set.points.size(), 2u);
  EXPECT_DOUBLE_EQ(set.points[0].fy_n, -100.5);
  EXPECT_DOUBLE_EQ(set.points[0].alpha_rad, 0.01);
  EXPECT_DOUBLE_EQ(set.points[0].fz_n, 4000.0);
  EXPECT_DOUBLE_EQ(set.points[0].vx_mps, 16.6);
  EXPECT_DOUBLE_EQ(set.points[0].gamma_rad, 0.0);
  EXPECT_TRUE(std::isnan(set.points[0].fx_n));
  EXPECT_TRUE(std::isnan(set.points[0].mz_nm));
  EXPECT_TRUE(std::isnan(set.points[1].fy_n));  // empty cell: not measured
  EXPECT_EQ(set.points[0].line, 4u);
  EXPECT_EQ(set.points[1].line, 5u);
}

// FSAE TTC style: the names and units tyre::InputTable knows (SA, IA in degrees, V in km/h), SAE
// axes converted to ISO-W (Fz, α, Fy, Mz change sign; κ, γ, Fx do not).
TEST(MeasurementCsv, TtcNamesInSaeAxes) {
  std::istringstream in(
      "ET,V,SA,IA,FZ,FX,FY,MZ,SL,P\n"
      "1.5,40,-4,2,-1100,150,2500,-30,0.02,82\n");
  const MeasurementSet set = read_measurement_csv(in, "ttc.csv", tyre::SignConvention::sae);
  ASSERT_EQ(set.points.size(), 1u);
  const MeasurementPoint& p = set.points[0];
  const double deg = std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(p.fz_n, 1100.0);
  EXPECT_DOUBLE_EQ(p.alpha_rad, 4.0 * deg);
  EXPECT_DOUBLE_EQ(p.gamma_rad, 2.0 * deg);
  EXPECT_DOUBLE_EQ(p.kappa, 0.02);
  EXPECT_DOUBLE_EQ(p.vx_mps, 40.0 / 3.6);
  EXPECT_DOUBLE_EQ(p.fx_n, 150.0);
  EXPECT_DOUBLE_EQ(p.fy_n, -2500.0);
  EXPECT_DOUBLE_EQ(p.mz_nm, 30.0);
  // The same file read as ISO-W keeps every sign.
  std::istringstream again("FZ,SA,SL,FY\n-1100,-4,0.02,2500\n");
  const MeasurementSet iso = read_measurement_csv(again, "iso.csv");
  EXPECT_DOUBLE_EQ(iso.points[0].fz_n, -1100.0);
  EXPECT_DOUBLE_EQ(iso.points[0].alpha_rad, -4.0 * deg);
  EXPECT_DOUBLE_EQ(iso.points[0].fy_n, 2500.0);
}

TEST(MeasurementCsv, BadRowsNameFileAndLine) {
  EXPECT_EQ(error_of("Fz_N,kappa,alpha_rad,Fx_N\n1,2,3,4\n1,x,3,4\n", false),
            "m.csv:3: kappa: 'x' is not a finite number");
  EXPECT_EQ(error_of("Fz_N,kappa,alpha_rad,Fx_N\n1,2,3\n", false),
            "m.csv:2: expected 4 cells, found 3");
  EXPECT_EQ(error_of("Fz_N,kappa,alpha_rad,Fx_N\n1,2,3,inf\n", false),
            "m.csv:2: Fx_N: 'inf' is not a finite number");
  EXPECT_EQ(error_of("# x\nkappa,alpha_rad,Fx_N\n", false),
            "m.csv:2: missing column 'Fz_N' (or one of its other names; see --help)");
  EXPECT_EQ(error_of("Fz_N,kappa,alpha_rad\n", false),
            "m.csv:1: no measured column (Fx_N, Fy_N or Mz_Nm, or one of their other names)");
  EXPECT_EQ(error_of("Fz_N,kappa,kappa,alpha_rad,Fx_N\n", false),
            "m.csv:1: columns 'kappa' and 'kappa' both give kappa");
  EXPECT_EQ(error_of("Fz_N,kappa,alpha_rad,FY,Fy_N\n", false),
            "m.csv:1: columns 'FY' and 'Fy_N' both give Fy_N");
  EXPECT_EQ(error_of("", false), "m.csv:0: no header row");
  // Finite as written, infinite once in SI units (found by fuzzing): refused, not carried as inf.
  EXPECT_EQ(error_of("Fz_kN,kappa,alpha_rad,Fx_N\n1e308,0,0,1\n", false),
            "m.csv:2: Fz_kN: '1e308' is out of range once converted to SI units");
}

// The fitter reads CSV as `tread mf eval` does (one reader, tyre::InputTable): ';' or tab
// separators with decimal commas, a units row under the header (FSAE TTC run files), which also
// sets the measured columns' units.
TEST(MeasurementCsv, SeparatorsDecimalCommasAndUnitsRowAsMfEval) {
  std::istringstream semicolon("Fz_N;kappa;alpha_deg;Fy_N;Mz_Nm\n4000;0,02;-2,5;1234,5;-7,25\n");
  const MeasurementSet a = read_measurement_csv(semicolon, "s.csv");
  ASSERT_EQ(a.points.size(), 1u);
  EXPECT_DOUBLE_EQ(a.points[0].kappa, 0.02);
  EXPECT_DOUBLE_EQ(a.points[0].alpha_rad, -2.5 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(a.points[0].fy_n, 1234.5);
  EXPECT_DOUBLE_EQ(a.points[0].mz_nm, -7.25);
  std::istringstream tab("FZ\tSL\tSA\tFX\n-1000\t0,1\t0\t2,5\n");
  const MeasurementSet b = read_measurement_csv(tab, "t.csv", tyre::SignConvention::sae);
  EXPECT_DOUBLE_EQ(b.points[0].fz_n, 1000.0);
  EXPECT_DOUBLE_EQ(b.points[0].fx_n, 2.5);
  // A TTC-style units row: lbf for the load and Fy, N-m for Mz, kph, psi (pressure: not fitted).
  std::istringstream units(
      "ET,V,SA,IA,FZ,FY,MZ,SL,P\n"
      "s,kph,deg,deg,lbf,lbf,N-m,1,psi\n"
      "1.5,40,-4,2,-250,500,-30,0.02,12\n");
  const MeasurementSet c = read_measurement_csv(units, "u.csv", tyre::SignConvention::sae);
  ASSERT_EQ(c.points.size(), 1u);
  EXPECT_DOUBLE_EQ(c.points[0].fz_n, 250.0 * 4.4482216152605);
  EXPECT_DOUBLE_EQ(c.points[0].fy_n, -500.0 * 4.4482216152605);
  EXPECT_DOUBLE_EQ(c.points[0].mz_nm, 30.0);
  EXPECT_EQ(c.points[0].line, 3u);
  EXPECT_TRUE(c.has_pressure);
  EXPECT_EQ(c.ignored_columns, (std::vector<std::string>{"ET", "P"}));
  // A unit the measured column cannot have is an error at the units row.
  EXPECT_EQ(error_of("FZ,SL,SA,MZ\nN,1,deg,N\n", false),
            "m.csv:2: unit 'N' of column 'MZ' is not a unit of Mz_Nm (expected n m, nm, n-m, "
            "n·m, n*m, kn m, knm, kn-m, kn·m, ft-lbf, lbf-ft)");
}

const char* const kTydex =
    "**HEADER\n"
    "RELEASE     1.3\n"
    "**COMMENTS\n"
    "written by measurement_test\n"
    "**CONSTANTS\n"
    "FZW         Vertical load                 N        4000\n"
    "**MEASURCHANNELS\n"
    "! name     description                   unit  factor  offsets\n"
    "RUNTIME     Time                          s        1  0  0\n"
    "FZW         Vertical force                kN       1  0  0\n"
    "SLIPANGL    Slip angle                    deg      1  0  0\n"
    "LONGSLIP    Longitudinal slip             %        1  0  0\n"
    "INCLANGL    Inclination angle             deg      1  0  0\n"
    "LONGVEL     Longitudinal velocity         km/h     1  0  0\n"
    "FYW         Lateral force                 N        2  0.5  10\n"
    "MZW         Self aligning moment          Nm       1  0  0\n"
    "**MEASURDATA\n"
    "0.0  4.0  2.0  0.0  1.0  36.0  -300  20\n"
    "0.1  4.1  -2.0  5.0  0.0  72.0  300  -20\n"
    "**END\n";

TEST(MeasurementTydex, ChannelsAndUnits) {
  std::istringstream in(kTydex);
  const MeasurementSet set = read_tydex(in, "m.tdx");
  ASSERT_EQ(set.points.size(), 2u);
  const double deg = std::numbers::pi / 180.0;
  const MeasurementPoint& p = set.points[0];
  EXPECT_DOUBLE_EQ(p.fz_n, 4000.0);
  EXPECT_DOUBLE_EQ(p.alpha_rad, 2.0 * deg);
  EXPECT_DOUBLE_EQ(p.gamma_rad, 1.0 * deg);
  EXPECT_DOUBLE_EQ(p.vx_mps, 10.0);
  EXPECT_DOUBLE_EQ(p.fy_n, (-300.0 - 0.5) * 2.0 + 10.0);
  EXPECT_DOUBLE_EQ(p.mz_nm, 20.0);
  EXPECT_TRUE(std::isnan(p.fx_n));
  EXPECT_EQ(p.line, 18u);
  EXPECT_DOUBLE_EQ(set.points[1].kappa, 0.05);
  EXPECT_DOUBLE_EQ(set.points[1].fz_n, 4100.0);
  EXPECT_DOUBLE_EQ(set.points[1].vx_mps, 20.0);
}

TEST(MeasurementTydex, BadRowsNameFileAndLine) {
  std::string short_row = kTydex;
  short_row.replace(short_row.find("0.1  4.1"), 8, "0.1");
  EXPECT_EQ(error_of(short_row, true), "m.tdx:19: expected 8 values, found 7");
  std::string bad_value = kTydex;
  bad_value.replace(bad_value.find("-300"), 4, "abc");
  EXPECT_EQ(error_of(bad_value, true), "m.tdx:18: value 7 'abc' is not a finite number");
  std::string bad_unit = kTydex;
  bad_unit.replace(bad_unit.find("km/h"), 4, "mph ");
  EXPECT_EQ(error_of(bad_unit, true), "m.tdx:14: unknown unit 'mph' of channel LONGVEL");
  std::string no_fz = kTydex;
  no_fz.replace(no_fz.find("FZW         Vertical force"), 3, "FZX");
  EXPECT_EQ(error_of(no_fz, true), "m.tdx:7: missing channel FZW");
  EXPECT_EQ(error_of("**HEADER\n", true), "m.tdx:1: no **MEASURDATA section");
  // A value that the channel's factor takes past the double range (found by fuzzing).
  std::string overflow = kTydex;
  overflow.replace(overflow.find("300  -20"), 3, "1e308");
  EXPECT_EQ(error_of(overflow, true),
            "m.tdx:19: value 7 '1e308' is out of range once the channel's factor, offsets and unit "
            "are applied");
}

}  // namespace
}  // namespace tread::fit
