// End-to-end test of `tread fit` (sim/cli/fit_command.cpp): runs the built CLI on noise-free
// measurements of a basic Magic Formula with known constants (CSV and TYDEX), checks the written
// constants, report and plots; bad input must fail with file:line and a non-zero exit status.
// Stage 2: --model mf61 on pure lateral data, --synthesize (deterministic per --seed) and the
// staged --model pac2002 fit of synthesized data read back as a .tir.
// A PAC2002 start refitted as MF 6.1 (--model mf61 --start PAC2002.tir).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fit/mf_staged_fit.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "test_dir.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_keys.hpp"
#include "tir/tir_units.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

std::filesystem::path tmp_dir() {
  // One scratch directory per test case: CTest runs the cases of this binary in parallel.
  return tread::testing::test_dir(std::string("fit_command_test_") +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

int run(const std::string& args, const std::filesystem::path& stderr_file) {
  const std::string command = std::string(TREAD_CLI) + " " + args + " 2> " + stderr_file.string();
  return std::system(command.c_str());
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The known curve, written out here (independent of the fitter's code).
double curve(double b, double c, double d, double e, double sh, double sv, double x) {
  const double bx = b * (x + sh);
  return d * std::sin(c * std::atan(bx - e * (bx - std::atan(bx)))) + sv;
}

struct Truth {
  double b, c, d, e, sh, sv;
};
// Lateral force per load: D grows with Fz, the shape stays.
Truth lateral(double fz) {
  return {9.0, 1.35, -0.95 * fz, -0.6, 0.003, 40.0};
}

/// Reads the fitter's CSV: channel_fz → column → value.
std::map<std::string, std::map<std::string, double>> read_fit(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) names.push_back(cell);
  }
  std::map<std::string, std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell, key;
    std::map<std::string, double> row;
    for (std::size_t i = 0; std::getline(s, cell, ','); ++i) {
      if (i == 0) {
        key = cell;
      } else {
        row[names[i]] = std::stod(cell);
      }
    }
    rows[key + "_" + std::to_string(std::lround(row["fz_N"]))] = row;
  }
  return rows;
}

TEST(FitCommand, CsvInRecoversKnownConstantsWithReportAndPlots) {
  const auto dir = tmp_dir();
  const auto in_csv = dir / "lateral.csv";
  {
    std::ofstream in(in_csv);
    in.precision(17);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_N\n";
    for (double fz : {3000.0, 5000.0}) {
      const Truth t = lateral(fz);
      for (int i = -40; i <= 40; ++i) {
        const double a = i * 0.005;
        in << fz << ",0," << a << ",0,16," << curve(t.b, t.c, t.d, t.e, t.sh, t.sv, a) << '\n';
      }
    }
  }
  const auto out_csv = dir / "fit.csv";
  const auto report = dir / "report.md";
  const auto plots = dir / "plots";
  std::filesystem::remove_all(plots);
  const auto err = dir / "stderr.txt";
  ASSERT_EQ(run("fit --model simple --input " + in_csv.string() + " --output " + out_csv.string() +
                    " --report " + report.string() + " --plots " + plots.string(),
                err),
            0)
      << slurp(err);
  EXPECT_NE(slurp(err).find("Fy(alpha) at Fz 3000 N: 81 points"), std::string::npos) << slurp(err);
  const auto rows = read_fit(out_csv);
  ASSERT_EQ(rows.size(), 2u);  // only Fy was measured
  for (double fz : {3000.0, 5000.0}) {
    const Truth t = lateral(fz);
    const auto& r = rows.at("Fy_N_" + std::to_string(std::lround(fz)));
    EXPECT_NEAR(r.at("D"), t.d, 1e-4 * std::fabs(t.d));
    EXPECT_NEAR(r.at("C"), t.c, 1e-4);
    EXPECT_NEAR(r.at("B"), t.b, 1e-4 * t.b);
    EXPECT_NEAR(r.at("E"), t.e, 1e-3);
    EXPECT_NEAR(r.at("SH"), t.sh, 1e-6);
    EXPECT_NEAR(r.at("SV"), t.sv, 1e-2);
    EXPECT_LT(r.at("rms"), 1e-3);
    EXPECT_NEAR(r.at("slope_at_origin"),
                (curve(t.b, t.c, t.d, t.e, t.sh, t.sv, 1e-6) -
                 curve(t.b, t.c, t.d, t.e, t.sh, t.sv, -1e-6)) /
                    2e-6,
                1e-4 * t.b * t.c * std::fabs(t.d));
  }
  const std::string md = slurp(report);
  EXPECT_NE(md.find("## Fy(alpha)"), std::string::npos);
  EXPECT_EQ(md.find("## Fx(kappa)"), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(plots / "Fy_N_Fz3000N.png"), 1000u);
  EXPECT_GT(std::filesystem::file_size(plots / "Fy_N_Fz5000N.png"), 1000u);
}

TEST(FitCommand, TydexInWithUnits) {
  const auto dir = tmp_dir();
  const auto in_tdx = dir / "long.tdx";
  const Truth t{12.0, 1.6, 4200.0, 0.3, 0.0, 0.0};
  {
    std::ofstream in(in_tdx);
    in.precision(17);
    in << "**HEADER\nRELEASE 1.3\n**MEASURCHANNELS\n"
       << "FZW       Vertical force                kN     1 0 0\n"
       << "LONGSLIP  Longitudinal slip             %      1 0 0\n"
       << "SLIPANGL  Slip angle                    deg    1 0 0\n"
       << "FXW       Longitudinal force            kN     1 0 0\n"
       << "**MEASURDATA\n";
    for (int i = -30; i <= 30; ++i) {
      const double kappa = i * 0.01;
      in << "4.0 " << 100.0 * kappa << " 0 "
         << curve(t.b, t.c, t.d, t.e, t.sh, t.sv, kappa) / 1000.0 << "\n";
    }
    in << "**END\n";
  }
  const auto out_csv = dir / "long_fit.csv";
  const auto err = dir / "stderr_tdx.txt";
  ASSERT_EQ(run("fit --input " + in_tdx.string() + " --output " + out_csv.string(), err), 0)
      << slurp(err);
  const auto rows = read_fit(out_csv);
  ASSERT_EQ(rows.count("Fx_N_4000"), 1u);
  const auto& r = rows.at("Fx_N_4000");
  EXPECT_NEAR(r.at("D"), t.d, 1e-4 * t.d);
  EXPECT_NEAR(r.at("C"), t.c, 1e-4);
  EXPECT_NEAR(r.at("B"), t.b, 1e-4 * t.b);
}

TEST(FitCommand, BadInputFailsWithFileAndLine) {
  const auto dir = tmp_dir();
  const auto in_csv = dir / "bad.csv";
  {
    std::ofstream in(in_csv);
    in << "Fz_N,kappa,alpha_rad,Fy_N\n4000,0,0.01,-300\n4000,0,zero,-300\n";
  }
  const auto err = dir / "stderr_bad.txt";
  EXPECT_NE(run("fit --input " + in_csv.string() + " --output " + (dir / "x.csv").string(), err),
            0);
  EXPECT_NE(slurp(err).find("bad.csv:3: alpha_rad: 'zero' is not a finite number"),
            std::string::npos)
      << slurp(err);
  EXPECT_NE(run("fit --input " + in_csv.string() + " --output " + (dir / "x.tir").string(), err),
            0);
  EXPECT_NE(slurp(err).find("writes the per-load constants as .csv"), std::string::npos)
      << slurp(err);
}

double fy_of(const tread::mf::MfParameters<double>& p, double fz, double alpha) {
  tread::mf::MfInput<double> in;
  in.fz_n = fz;
  in.alpha_rad = alpha;
  in.vx_mps = 16.6;
  tread::mf::MfOptions o;
  o.combined = false;
  return tread::mf::evaluate(p, in, o).fy_n;
}

// Braking-only points of the MF 6.1 sample tyre (κ from -0.3 to -0.0025, the set of an audit) do
// not determine every constant of the simple formula: the covariance is rank deficient. The fit
// says so where it writes nan; Ceres's own log line (glog: "Covariance matrix is near rank
// deficient", after "Logging before InitGoogleLogging()") is not passed through.
TEST(FitCommand, UndeterminedStandardDeviationsAreSaid) {
  const auto truth =
      tread::tyre::load_mf_parameters(tread::testing::tyre_file("MagicFormula61_Parameters.tir"))
          .params;
  const auto dir = tmp_dir();
  const auto in_csv = dir / "braking.csv";
  {
    std::ofstream in(in_csv);
    in.precision(17);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fx_N\n";
    std::vector<double> kappas;
    for (int i = 30; i >= 5; --i) kappas.push_back(-0.01 * i);
    for (int i = 19; i >= 1; --i) kappas.push_back(-0.0025 * i);
    kappas.push_back(-0.1);
    for (const double kappa : kappas) {
      tread::mf::MfInput<double> x;
      x.fz_n = 6752.0;
      x.kappa = kappa;
      x.vx_mps = 16.7;
      tread::mf::MfOptions o;
      o.combined = false;
      in << "6752," << kappa << ",0,0,16.7," << tread::mf::evaluate(truth, x, o).fx_n << '\n';
    }
  }
  const auto err = dir / "stderr.txt";
  const auto out_csv = dir / "fit.csv";
  ASSERT_EQ(run("fit --input " + in_csv.string() + " --output " + out_csv.string(), err), 0)
      << slurp(err);
  const std::string e = slurp(err);
  EXPECT_EQ(e.find("InitGoogleLogging"), std::string::npos) << e;
  EXPECT_EQ(e.find("covariance_impl"), std::string::npos) << e;
  const auto rows = read_fit(out_csv);
  ASSERT_EQ(rows.size(), 1U);
  const auto& r = rows.begin()->second;
  bool nan = false;
  for (const char* k : {"sd_B", "sd_C", "sd_D", "sd_E", "sd_SH", "sd_SV"}) {
    nan = nan || !std::isfinite(r.at(k));
  }
  EXPECT_EQ(e.find("standard deviations not determined") != std::string::npos, nan) << e;
}

// Stage 2: --model mf61 fits the pure lateral coefficients from a neutral start .tir and writes a
// .tir that the Magic Formula reader (the one `tread mf eval` uses) reads back.
TEST(FitCommand, Mf61PureLateralWritesTir) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(tir)) << tir;
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const auto dir = tmp_dir();
  const auto start_tir = dir / "start.tir";
  {
    tread::tir::TirFile file = tread::tir::read_tir(tir);
    for (const char* key : {"PCY1", "PDY1", "PDY2", "PEY1", "PEY2", "PEY3", "PKY1", "PKY2", "PKY4",
                            "PHY1", "PHY2", "PVY1", "PVY2"}) {
      file.erase("LATERAL_COEFFICIENTS", key);  // → the book defaults
    }
    tread::tir::write_tir(file, start_tir);
  }
  const auto in_csv = dir / "mf61_lateral.csv";
  {
    std::ofstream in(in_csv);
    in.precision(17);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_N\n";
    for (double fz : {2000.0, 4000.0, 6000.0}) {
      for (int i = -60; i <= 60; ++i) {
        in << fz << ",0," << i * 0.005 << ",0,16.6," << fy_of(truth, fz, i * 0.005) << '\n';
      }
    }
  }
  const auto out_tir = dir / "fitted.tir";
  const auto report = dir / "mf61_report.md";
  const auto err = dir / "stderr_mf61.txt";
  ASSERT_EQ(run("fit --model mf61 --start " + start_tir.string() + " --input " + in_csv.string() +
                    " --output " + out_tir.string() + " --report " + report.string(),
                err),
            0)
      << slurp(err);
  EXPECT_NE(slurp(err).find("iteration 1:"), std::string::npos);
  EXPECT_NE(slurp(report).find("| PKY1 |"), std::string::npos);
  const tread::mf::MfParameters<double> fitted = tread::tyre::load_mf_parameters(out_tir).params;
  for (double fz : {2000.0, 4000.0, 6000.0}) {
    double ss = 0.0, peak = 0.0;
    int n = 0;
    for (int i = -300; i <= 300; ++i, ++n) {
      const double t = fy_of(truth, fz, i * 1e-3);
      const double d = fy_of(fitted, fz, i * 1e-3) - t;
      ss += d * d;
      peak = std::max(peak, std::fabs(t));
    }
    EXPECT_LT(std::sqrt(ss / n), 1e-3 * peak) << fz;  // noise-free data: a near-exact fit
  }
}

// --synthesize writes the same file for the same --seed and a different one for another seed.
TEST(FitCommand, SynthesizeIsDeterministicPerSeed) {
  const auto tir = tread::testing::tyre_file("chrono_Sedan_Pac02Tire.tir");
  ASSERT_TRUE(std::filesystem::exists(tir)) << tir;
  const auto dir = tmp_dir();
  const auto err = dir / "stderr_synth.txt";
  for (const char* name : {"synth_a.csv", "synth_b.csv"}) {
    ASSERT_EQ(
        run("fit --synthesize " + tir.string() + " --seed 42 --output " + (dir / name).string(),
            err),
        0)
        << slurp(err);
  }
  ASSERT_EQ(run("fit --synthesize " + tir.string() + " --seed 43 --output " +
                    (dir / "synth_c.csv").string(),
                err),
            0)
      << slurp(err);
  // CSV under a .tir name: refused (it was written).
  EXPECT_NE(
      run("fit --synthesize " + tir.string() + " --output " + (dir / "synth.tir").string(), err),
      0);
  EXPECT_NE(slurp(err).find("--synthesize writes measurements as CSV, not a .tir"),
            std::string::npos)
      << slurp(err);
  EXPECT_FALSE(std::filesystem::exists(dir / "synth.tir"));
  const std::string a = slurp(dir / "synth_a.csv");
  EXPECT_GT(a.size(), 100000u);
  EXPECT_EQ(a, slurp(dir / "synth_b.csv"));
  EXPECT_NE(a.substr(a.find('\n')), slurp(dir / "synth_c.csv").substr(a.find('\n')));
}

double value_of(const tread::mf::MfParameters<double>& p, double fz, double kappa, double alpha,
                int channel) {
  tread::mf::MfInput<double> in;
  in.fz_n = fz;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.vx_mps = 16.7;
  const auto out = tread::mf::evaluate(p, in, tread::mf::MfOptions{});
  return channel == 0 ? out.fx_n : out.fy_n;
}

// Pure Fx(κ) and Fy(α) of the fitted tyre against the truth at each load, κ and α over ±0.3:
// RMS difference below 1 % of the truth's peak.
void expect_pure_curves_within_1_percent(const tread::mf::MfParameters<double>& truth,
                                         const tread::mf::MfParameters<double>& fitted,
                                         std::initializer_list<double> loads_n) {
  for (double fz : loads_n) {
    for (int channel : {0, 1}) {
      double ss = 0.0, peak = 0.0;
      int n = 0;
      for (int i = -300; i <= 300; ++i, ++n) {
        const double x = i * 1e-3;
        const double t = channel == 0 ? value_of(truth, fz, x, 0, 0) : value_of(truth, fz, 0, x, 1);
        const double f =
            channel == 0 ? value_of(fitted, fz, x, 0, 0) : value_of(fitted, fz, 0, x, 1);
        ss += (f - t) * (f - t);
        peak = std::max(peak, std::fabs(t));
      }
      EXPECT_LT(std::sqrt(ss / n), 0.01 * peak) << fz << " channel " << channel;
    }
  }
}

// Stage 2 end to end, PAC2002: --synthesize, then --model pac2002 --neutral-start from the same
// file; the written .tir is read back by the reader `tread mf eval` uses (and by `tread mf eval`
// itself); report, plots and progress lines are written.
TEST(FitCommand, Pac2002StagedFitFromSynthesizedData) {
  const auto tir = tread::testing::tyre_file("chrono_Sedan_Pac02Tire.tir");
  ASSERT_TRUE(std::filesystem::exists(tir)) << tir;
  const auto dir = tmp_dir();
  const auto data = dir / "pac2002_data.csv";
  const auto out_tir = dir / "pac2002_fit.tir";
  const auto report = dir / "pac2002_report.md";
  const auto plots = dir / "pac2002_plots";
  const auto err = dir / "stderr_pac2002.txt";
  std::filesystem::remove_all(plots);
  ASSERT_EQ(run("fit --synthesize " + tir.string() + " --seed 7 --output " + data.string(), err), 0)
      << slurp(err);
  ASSERT_EQ(run("fit --model pac2002 --neutral-start --start " + tir.string() + " --input " +
                    data.string() + " --output " + out_tir.string() + " --report " +
                    report.string() + " --plots " + plots.string(),
                err),
            0)
      << slurp(err);
  EXPECT_NE(slurp(err).find("Fy0 (gamma = 0): iteration 1:"), std::string::npos);
  const std::string r = slurp(report);
  for (const char* stage :
       {"## Fx0 (gamma = 0)", "## Fy0 (all cambers)", "## Mz0 (all cambers)", "## Fx (combined)",
        "## Fy (combined)", "## Mz (combined)", "| QDZ8 |", "| RVY1 |", "| SSZ1 |"}) {
    EXPECT_NE(r.find(stage), std::string::npos) << stage;
  }
  for (const char* png : {"Fx_Fz4850N.png", "Fy_Fz2425N.png", "Mz_Fz7275N.png"}) {
    EXPECT_TRUE(std::filesystem::exists(plots / png)) << png;
  }
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const tread::mf::MfParameters<double> fitted = tread::tyre::load_mf_parameters(out_tir).params;
  EXPECT_EQ(fitted.fit_type, tread::mf::FitType::pac2002);
  expect_pure_curves_within_1_percent(truth, fitted, {2425.0, 4850.0, 7275.0});
  const auto in_csv = dir / "pac2002_eval_in.csv";
  {
    std::ofstream in(in_csv);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps\n4850,0.05,0.03,0.02,16.7\n";
  }
  EXPECT_EQ(run("mf eval --tir " + out_tir.string() + " --input " + in_csv.string() + " --output " +
                    (dir / "pac2002_eval_out.csv").string(),
                err),
            0)
      << slurp(err);
  // The wrong model for the start file is refused with a message: an MF 6.1 file is not refitted
  // as PAC2002 (the other way round works: Mf61RefitOfAPac2002File).
  const auto mf61 = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  EXPECT_NE(run("fit --model pac2002 --start " + mf61.string() + " --input " + data.string() +
                    " --output " + (dir / "wrong.tir").string(),
                err),
            0);
  EXPECT_NE(slurp(err).find("--model pac2002 needs a PAC2002"), std::string::npos) << slurp(err);
}

// A PAC2002 file refitted as MF 6.1: synthesized from the PAC2002 file, fitted with --model mf61
// --start PAC2002.tir, written as an MF 6.1 file (FITTYP 61, PAC2002-only keys removed) whose
// curves follow the PAC2002 tyre's; the fit error is reported per channel and load.
TEST(FitCommand, Mf61RefitOfAPac2002File) {
  const auto tir = tread::testing::tyre_file("chrono_VW_mf_185_80R14_PAC2002.tir");
  const auto dir = tmp_dir();
  const auto data = dir / "refit_data.csv";
  const auto out_tir = dir / "refit_mf61.tir";
  const auto err = dir / "stderr_refit.txt";
  ASSERT_EQ(run("fit --synthesize " + tir.string() + " --seed 3 --output " + data.string(), err), 0)
      << slurp(err);
  ASSERT_EQ(run("fit --model mf61 --start " + tir.string() + " --input " + data.string() +
                    " --output " + out_tir.string(),
                err),
            0)
      << slurp(err);
  const std::string e = slurp(err);
  EXPECT_NE(e.find("a PAC2002 / MF 5.2 start, refitted as MF 6.1"), std::string::npos) << e;
  EXPECT_NE(e.find("note: PHY3 = "), std::string::npos) << e;
  EXPECT_NE(e.find("removed: LGAX LGAY LGAZ PHY3"), std::string::npos) << e;
  EXPECT_NE(e.find("fit error Fy at Fz = "), std::string::npos) << e;
  EXPECT_NE(e.find("fit error Mz at Fz = "), std::string::npos) << e;

  const tread::tir::TirFile written = tread::tir::read_tir(out_tir);
  EXPECT_EQ(written.number_any("FITTYP"), 61.0);
  EXPECT_EQ(written.text_any("PROPERTY_FILE_FORMAT"), "USER");
  for (const char* key : {"LGAY", "PHY3", "PTX1"}) EXPECT_EQ(written.find_any(key), nullptr) << key;
  for (const char* key : {"PKY4", "PKY6", "PPX1", "INFLPRES", "NOMPRES"}) {
    EXPECT_NE(written.find_any(key), nullptr) << key;
  }
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const tread::mf::MfParameters<double> fitted = tread::tyre::load_mf_parameters(out_tir).params;
  EXPECT_EQ(fitted.fit_type, tread::mf::FitType::mf61);
  expect_pure_curves_within_1_percent(truth, fitted, {2000.0, 4000.0, 5500.0});
}

// A PAC2002 start whose [UNITS] are mm, kN and kPa, refitted as MF 6.1: the keys MF 6.1 adds
// (NOMPRES, the structural stiffnesses, BOTTOM_OFFST) are written in the file's units, so the
// fitted file reads back as the SI start's fit does (they had been written as SI numbers: NOMPRES
// 220000 read as 220 MPa).
TEST(FitCommand, Mf61RefitWritesAddedKeysInTheStartsUnits) {
  const auto tir = tread::testing::tyre_file("chrono_VW_mf_185_80R14_PAC2002.tir");
  const auto dir = tmp_dir();
  const auto err = dir / "stderr.txt";
  const auto mm_tir = dir / "start_mm.tir";
  {
    // Every dimensional value rewritten in mm, kN and kPa, [UNITS] saying so.
    tread::tir::TirFile file = tread::tir::read_tir(tir);
    const tread::tir::UnitSystem si = tread::tir::read_units(file);
    std::vector<std::pair<std::string, std::pair<std::string, double>>> values;
    for (const tread::tir::Section& section : file.sections()) {
      if (section.is_table()) continue;
      for (const tread::tir::Entry* e : section.entries()) {
        const tread::tir::KeyInfo* info = tread::tir::find_key_info(e->key);
        if (info == nullptr || e->is_quoted() || info->dimension.is_none()) continue;
        values.push_back(
            {section.name, {e->key, *tread::tir::number_si(file, si, section.name, e->key)}});
      }
    }
    file.set_text("UNITS", "LENGTH", "mm");
    file.set_text("UNITS", "FORCE", "kN");
    file.set_text("UNITS", "PRESSURE", "kPa");
    for (const auto& [section, kv] : values) tread::tir::set_si(file, section, kv.first, kv.second);
    tread::tir::write_tir(file, mm_tir);
  }
  const auto data = dir / "data.csv";
  ASSERT_EQ(run("fit --synthesize " + tir.string() + " --seed 3 --output " + data.string(), err), 0)
      << slurp(err);
  const auto fitted = [&](const std::filesystem::path& start, const char* name) {
    const auto out = dir / name;
    EXPECT_EQ(run("fit --model mf61 --start " + start.string() + " --input " + data.string() +
                      " --output " + out.string(),
                  err),
              0)
        << slurp(err);
    return tread::tyre::load_mf_parameters(out).params;
  };
  const tread::mf::MfParameters<double> si = fitted(tir, "si.tir");
  const tread::mf::MfParameters<double> mm = fitted(mm_tir, "mm.tir");
  EXPECT_NEAR(mm.nompres_pa, si.nompres_pa, 1e-9 * si.nompres_pa);
  EXPECT_NEAR(mm.inflpres_pa, si.inflpres_pa, 1e-9 * si.inflpres_pa);
  EXPECT_NEAR(mm.longitudinal_stiffness_npm, si.longitudinal_stiffness_npm,
              1e-9 * si.longitudinal_stiffness_npm);
  EXPECT_NEAR(mm.lateral_stiffness_npm, si.lateral_stiffness_npm, 1e-9 * si.lateral_stiffness_npm);
  EXPECT_NEAR(mm.bottom_offst_m, si.bottom_offst_m, 1e-12);
}

// The staged fit: a point at Vx = 0 (or a file without Vx) is an error naming its line, not a
// crash in the covariance (a NaN Jacobian); a pressure column and other unread columns are said;
// an Fx_kN column is read in kN.
TEST(FitCommand, StagedFitInputsAreCheckedAndSaid) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const auto dir = tmp_dir();
  const auto err = dir / "stderr.txt";
  const auto write_csv = [&](const char* name, const char* header, double vx_first) {
    const auto path = dir / name;
    std::ofstream in(path);
    in.precision(17);
    in << header << '\n';
    int row = 0;
    for (double fz : {2000.0, 4000.0, 6000.0}) {
      for (int i = -40; i <= 40; ++i, ++row) {
        const double alpha = i * 0.005;
        in << fz << ",0," << alpha << ",0," << (row == 5 ? vx_first : 16.6) << ','
           << fy_of(truth, fz, alpha) / 1000.0 << ",220\n";
      }
    }
    return path;
  };
  const auto stopped =
      write_csv("stopped.csv", "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_kN,P_kPa", 0.0);
  EXPECT_NE(run("fit --model mf61 --start " + tir.string() + " --input " + stopped.string() +
                    " --output " + (dir / "x.tir").string(),
                err),
            0);
  EXPECT_NE(slurp(err).find("stopped.csv:7: Vx = 0"), std::string::npos) << slurp(err);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.tir"));

  // Loads in kN under an N column (2, 4, 6 "N"): 1/1000 of FNOMIN, refused (it fitted a μ of
  // 76 686 and wrote it). Nothing is written.
  const auto kn = dir / "kn.csv";
  {
    std::ifstream from(
        write_csv("n.csv", "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_kN,P_kPa", 16.6));
    std::ofstream to(kn);
    std::string line;
    std::getline(from, line);
    to << line << '\n';
    while (std::getline(from, line)) {
      const auto comma = line.find(',');
      to << std::stod(line.substr(0, comma)) / 1000.0 << line.substr(comma) << '\n';
    }
  }
  EXPECT_NE(run("fit --model mf61 --start " + tir.string() + " --input " + kn.string() +
                    " --output " + (dir / "kn.tir").string(),
                err),
            0);
  EXPECT_NE(slurp(err).find("kn.csv: the loads' median is 4 N, 0.0005924 × the start file's "
                            "FNOMIN (6752 N): loads in kN or lbf"),
            std::string::npos)
      << slurp(err);
  EXPECT_FALSE(std::filesystem::exists(dir / "kn.tir"));

  const auto good =
      write_csv("good.csv", "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_kN,P_kPa", 16.6);
  ASSERT_EQ(run("fit --model mf61 --start " + tir.string() + " --input " + good.string() +
                    " --output " + (dir / "good.tir").string(),
                err),
            0)
      << slurp(err);
  const std::string e = slurp(err);
  EXPECT_NE(e.find("ignored columns: 'P_kPa'"), std::string::npos) << e;
  EXPECT_NE(e.find("warning: the pressure column is not used: every point is fitted as if "
                   "measured at the start file's INFLPRES (260000 Pa)"),
            std::string::npos)
      << e;
  // The kN column is the Fy fitted (near-exact on noise-free data).
  EXPECT_NE(e.find("fit error Fy at Fz = 4000 N"), std::string::npos) << e;
  const tread::mf::MfParameters<double> fitted =
      tread::tyre::load_mf_parameters(dir / "good.tir").params;
  EXPECT_NEAR(fy_of(fitted, 4000.0, 0.05), fy_of(truth, 4000.0, 0.05),
              1e-3 * std::fabs(fy_of(truth, 4000.0, 0.05)));
}

// --neutral-start with data for some stages only: the coefficients no stage fitted are written at
// the book values the fit used, so that the reported fit error describes the written file.
TEST(FitCommand, NeutralStartWritesWhatTheFitErrorDescribes) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const auto dir = tmp_dir();
  const auto err = dir / "stderr.txt";
  const auto in_csv = dir / "lateral.csv";
  {
    std::ofstream in(in_csv);
    in.precision(17);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_N\n";
    for (double fz : {2000.0, 4000.0, 6000.0}) {
      for (int i = -40; i <= 40; ++i) {
        in << fz << ",0," << i * 0.005 << ",0,16.6," << fy_of(truth, fz, i * 0.005) << '\n';
      }
    }
  }
  const auto out = dir / "neutral.tir";
  ASSERT_EQ(run("fit --model mf61 --neutral-start --start " + tir.string() + " --input " +
                    in_csv.string() + " --output " + out.string(),
                err),
            0)
      << slurp(err);
  const std::string e = slurp(err);
  EXPECT_NE(e.find("warning: --neutral-start: no stage fitted"), std::string::npos) << e;
  // Fx had no data: its coefficients are the book's in the file, as in the fit.
  const tread::mf::MfParameters<double> fitted = tread::tyre::load_mf_parameters(out).params;
  const tread::mf::MfParameters<double> book =
      tread::fit::neutral_start(truth, tread::fit::MfFitModel::mf61);
  EXPECT_EQ(fitted.pdx1, book.pdx1);
  EXPECT_EQ(fitted.pkx1, book.pkx1);
  EXPECT_NE(fitted.pdx1, truth.pdx1);
}

// Numbers the fit would print or write silently wrong: loads with z down read as ISO-W, points off
// the ground, a mirror-image tyre (α or Fy in another convention), a load level so alone that the
// load terms are not determined (held at the start's values, said, "held" in the report), a fit
// worse than the mean (nothing written) and a non-finite --noise.
TEST(FitCommand, DataTheFitCannotTakeAsWrittenAreSaid) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const tread::mf::MfParameters<double> truth = tread::tyre::load_mf_parameters(tir).params;
  const auto dir = tmp_dir();
  const auto err = dir / "stderr.txt";
  // sign_fz, sign_alpha: the file's signs; unloaded: every 20th point gets Fz = 0; flip_level:
  // that load's Fy is written mirrored.
  const auto write_csv = [&](const char* name, std::initializer_list<double> loads, double sign_fz,
                             double sign_alpha, bool unloaded, double flip_level) {
    const auto path = dir / name;
    std::ofstream in(path);
    in.precision(17);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fy_N\n";
    int row = 0;
    for (double fz : loads) {
      for (int i = -40; i <= 40; ++i, ++row) {
        const double alpha = i * 0.005;
        const double fy = fy_of(truth, fz, alpha) * (std::fabs(fz - flip_level) < 0.5 ? -1.0 : 1.0);
        in << (unloaded && row % 20 == 7 ? 0.0 : sign_fz * fz) << ",0," << sign_alpha * alpha
           << ",0,16.6," << fy << '\n';
      }
    }
    return path;
  };
  const std::string start = " --start " + tir.string();
  const auto sae = write_csv("sae.csv", {2000.0, 4000.0, 6000.0}, -1.0, 1.0, false, 0.0);
  EXPECT_NE(run("fit --model mf61" + start + " --input " + sae.string() + " --output " +
                    (dir / "sae.tir").string(),
                err),
            0);
  EXPECT_NE(slurp(err).find("sae.csv:2: Fz = -2000 N: 243 of 243 points have a load ≤ 0"),
            std::string::npos)
      << slurp(err);
  EXPECT_NE(slurp(err).find("--convention sae"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "sae.tir"));

  const auto lifted = write_csv("lifted.csv", {2000.0, 4000.0, 6000.0}, 1.0, 1.0, true, 0.0);
  ASSERT_EQ(
      run("fit --input " + lifted.string() + " --output " + (dir / "lifted.csv").string(), err), 0)
      << slurp(err);
  EXPECT_NE(slurp(err).find("warning: 12 points with Fz ≤ 0 (a wheel off the ground) are not "
                            "fitted; the first at " +
                            lifted.string() + ":9"),
            std::string::npos)
      << slurp(err);

  const auto mirrored = write_csv("mirror.csv", {2000.0, 4000.0}, 1.0, -1.0, false, 0.0);
  ASSERT_EQ(run("fit --input " + mirrored.string() + " --output " + (dir / "m.csv").string(), err),
            0)
      << slurp(err);
  EXPECT_NE(slurp(err).find("warning: the fitted dFy/dalpha is "), std::string::npos) << slurp(err);
  EXPECT_NE(slurp(err).find("--convention adapted-iso"), std::string::npos) << slurp(err);

  // One load level: PDY2, PKY2, ... act only as PDY1, PKY1, ... do there.
  const auto one = write_csv("one.csv", {4000.0}, 1.0, 1.0, false, 0.0);
  const auto report = dir / "one.md";
  ASSERT_EQ(run("fit --model mf61" + start + " --input " + one.string() + " --output " +
                    (dir / "one.tir").string() + " --report " + report.string(),
                err),
            0)
      << slurp(err);
  EXPECT_NE(slurp(err).find(
                "not determined by these points, held at their values before the stage: PDY2"),
            std::string::npos)
      << slurp(err);
  EXPECT_NE(slurp(report).find("| PDY2 | "), std::string::npos);
  EXPECT_NE(slurp(report).find("held (not determined by these points)"), std::string::npos);
  const tread::mf::MfParameters<double> one_fit =
      tread::tyre::load_mf_parameters(dir / "one.tir").params;
  EXPECT_EQ(one_fit.pdy2, truth.pdy2);
  EXPECT_NEAR(fy_of(one_fit, 4000.0, 0.05), fy_of(truth, 4000.0, 0.05),
              1e-3 * std::fabs(fy_of(truth, 4000.0, 0.05)));

  // The 6000 N level written mirrored: no coefficient set fits all three; R² < 0 is a failure.
  const auto mixed = write_csv("mixed.csv", {2000.0, 4000.0, 6000.0}, 1.0, 1.0, false, 6000.0);
  EXPECT_NE(run("fit --model mf61" + start + " --input " + mixed.string() + " --output " +
                    (dir / "mixed.tir").string(),
                err),
            0);
  EXPECT_NE(slurp(err).find("the fit failed: R² < 0"), std::string::npos) << slurp(err);
  EXPECT_FALSE(std::filesystem::exists(dir / "mixed.tir"));

  for (const char* noise : {"nan", "inf", "-0.1", "1e308"}) {  // 1e308 wrote rows of inf
    EXPECT_NE(run("fit --synthesize " + tir.string() + " --noise " + noise + " --output " +
                      (dir / "noise.csv").string(),
                  err),
              0)
        << noise;
    EXPECT_NE(slurp(err).find("the noise level is a share of each channel's peak, from 0 to 1"),
              std::string::npos)
        << slurp(err);
  }
  // Options of the other mode are refused, not ignored.
  const std::string synth =
      "fit --synthesize " + tir.string() + " --output " + (dir / "s.csv").string();
  EXPECT_NE(run(synth + " --input " + mixed.string(), err), 0);
  EXPECT_NE(slurp(err).find("--input: applies to a fit, not to --synthesize"), std::string::npos)
      << slurp(err);
  EXPECT_NE(
      run("fit --input " + mixed.string() + " --noise 0.1 --output " + (dir / "n.csv").string(),
          err),
      0);
  EXPECT_NE(slurp(err).find("--noise: applies to --synthesize only"), std::string::npos)
      << slurp(err);
  EXPECT_NE(
      run("fit --input " + mixed.string() + start + " --output " + (dir / "n.csv").string(), err),
      0);
  EXPECT_NE(slurp(err).find("--start: applies to --model mf61 or pac2002"), std::string::npos)
      << slurp(err);
}

}  // namespace
