// End-to-end tests of `tread tir convert` (sim/cli/tir_command.cpp): a normalised rewrite keeps
// every section, key, value text and table row, drops every comment, and evaluates the same; a
// Chrono PAC89 JSON becomes a PAC89 property file; failures leave no output behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "test_dir.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_file.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "tyre/mf_tyre_figures.hpp"

namespace tread {
namespace {

namespace fs = std::filesystem;

// One scratch directory per test case: CTest runs the cases of this binary in parallel.
fs::path tmp_dir() {
  return testing::test_dir(std::string("tir_command_test_") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

int run(const std::string& args, const fs::path& stderr_file) {
  const std::string command = std::string(TREAD_CLI) + " " + args + " 2> " + stderr_file.string();
  return std::system(command.c_str());
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TirConvert, KeepsEveryValueDropsEveryComment) {
  const fs::path dir = tmp_dir();
  // Comments everywhere a .tir has them, CRLF line ends, a table section with a trailing comment.
  const fs::path in = dir / "commented.tir";
  {
    std::ofstream f(in, std::ios::binary);
    f << "$ a vendor's banner\r\n"
         "[MDI_HEADER]   $ header comment\r\n"
         "FILE_TYPE = 'tir'\r\n"
         "FILE_VERSION = 3.0   ! bang comment\r\n"
         "$----------------------------------model\r\n"
         "[MODEL]\r\n"
         "FITTYP = 61  $ Magic Formula version\r\n"
         "TYRESIDE = \"LEFT\"\r\n"
         "[VERTICAL]\r\n"
         "FNOMIN = 4.85D+03 $ Fortran exponent kept as written\r\n"
         "[DEFLECTION_LOAD_CURVE]\r\n"
         "{pen     fz}\r\n"
         " 0.000   0.0   $ first row\r\n"
         " 0.001   212\r\n";
  }
  const fs::path out = dir / "normalised.tir";
  ASSERT_EQ(run("tir convert " + in.string() + " " + out.string() + " --note 'made in a test'",
                dir / "stderr.txt"),
            0)
      << slurp(dir / "stderr.txt");
  EXPECT_EQ(slurp(out),
            "$ made in a test\n"
            "[MDI_HEADER]\n"
            "FILE_TYPE                = 'tir'\n"
            "FILE_VERSION             = 3.0\n"
            "[MODEL]\n"
            "FITTYP                   = 61\n"
            "TYRESIDE                 = \"LEFT\"\n"
            "[VERTICAL]\n"
            "FNOMIN                   = 4.85D+03\n"
            "[DEFLECTION_LOAD_CURVE]\n"
            "{pen     fz}\n"
            "0.000   0.0\n"
            "0.001   212\n");
  EXPECT_DOUBLE_EQ(*tir::read_tir(out).number("VERTICAL", "FNOMIN"), 4850.0);
}

TEST(TirConvert, NormalisedTyreEvaluatesTheSame) {
  const fs::path dir = tmp_dir();
  for (const char* name : {"MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                           "chrono_VW_mf_185_80R14_PAC2002.tir"}) {
    const fs::path src = testing::tyre_file(name);
    const fs::path out = dir / name;
    ASSERT_EQ(run("tir convert " + src.string() + " " + out.string(), dir / "stderr.txt"), 0)
        << slurp(dir / "stderr.txt");
    EXPECT_EQ(slurp(out).rfind("$ normalised by tread tir convert from " + std::string(name), 0),
              0u);
    const auto a = tyre::load_mf_parameters(src).params;
    const auto b = tyre::load_mf_parameters(out).params;
    mf::MfInput<double> x;
    x.fz_n = 4500.0;
    x.kappa = 0.05;
    x.alpha_rad = -0.07;
    x.gamma_rad = 0.02;
    x.vx_mps = 20.0;
    const auto ra = mf::evaluate(a, x, mf::MfOptions{});
    const auto rb = mf::evaluate(b, x, mf::MfOptions{});
    EXPECT_EQ(ra.fx_n, rb.fx_n) << name;
    EXPECT_EQ(ra.fy_n, rb.fy_n) << name;
    EXPECT_EQ(ra.mz_nm, rb.mz_nm) << name;
  }
}

TEST(TirConvert, ChronoPac89JsonBecomesAPac89File) {
  const fs::path dir = tmp_dir();
  const fs::path json = testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json");
  const fs::path out = dir / "hmmwv.tir";
  ASSERT_EQ(run("tir convert " + json.string() + " " + out.string(), dir / "stderr.txt"), 0)
      << slurp(dir / "stderr.txt");
  const tir::TirFile f = tir::read_tir(out);
  EXPECT_EQ(f.text("MODEL", "PROPERTY_FILE_FORMAT"), "PAC89");
  const auto from_json = tir::pac_from_chrono_json(json);
  const auto from_tir = tir::pac_from_tir(f);
  EXPECT_EQ(from_tir.params.a, from_json.params.a);
  EXPECT_EQ(from_tir.params.b, from_json.params.b);
  EXPECT_EQ(from_tir.params.c, from_json.params.c);
  EXPECT_EQ(from_tir.params.unloaded_radius_m, from_json.params.unloaded_radius_m);
  // What the .tir has no place for is named (it was dropped without a word).
  EXPECT_NE(slurp(dir / "stderr.txt")
                .find("not in the PAC89 .tir (its coefficients and R0, rolling resistance and "
                      "lateral stiffness are): Coefficient of Friction"),
            std::string::npos)
      << slurp(dir / "stderr.txt");
  EXPECT_NE(slurp(dir / "stderr.txt").find("Design Parameters.Width"), std::string::npos);
}

TEST(TirConvert, BadInputFailsWithFileAndLineAndWritesNothing) {
  const fs::path dir = tmp_dir();
  const fs::path in = dir / "broken.tir";
  {
    std::ofstream f(in);
    f << "[MODEL]\nFITTYP = 61\nPDX1 = 'unterminated\n";
  }
  const fs::path out = dir / "broken_out.tir";
  fs::remove(out);
  EXPECT_NE(run("tir convert " + in.string() + " " + out.string(), dir / "stderr.txt"), 0);
  EXPECT_NE(slurp(dir / "stderr.txt").find("broken.tir:3:"), std::string::npos)
      << slurp(dir / "stderr.txt");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir / "broken_out.tir.tmp"));
  // An unwritable destination: an error, and the destination directory is left as it was.
  EXPECT_NE(run("tir convert " + testing::tyre_file("MagicFormula61_Parameters.tir").string() +
                    " " + (dir / "no_such_dir" / "x.tir").string(),
                dir / "stderr.txt"),
            0);
  EXPECT_NE(slurp(dir / "stderr.txt").find("cannot write"), std::string::npos);
  // An empty input is not a property file; an output that is not a .tir is refused (a .json
  // name got .tir text).
  std::ofstream(dir / "empty.tir").close();
  EXPECT_NE(run("tir convert " + (dir / "empty.tir").string() + " " + (dir / "e.tir").string(),
                dir / "stderr.txt"),
            0);
  EXPECT_NE(slurp(dir / "stderr.txt").find("no [SECTION] in it"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "e.tir"));
  EXPECT_NE(run("tir convert " + testing::tyre_file("MagicFormula61_Parameters.tir").string() +
                    " " + (dir / "x.json").string(),
                dir / "stderr.txt"),
            0);
  EXPECT_NE(slurp(dir / "stderr.txt").find("writes a .tir property file"), std::string::npos);
}

struct Output {
  int status;
  std::string out;
};

Output info(const fs::path& file) {
  const fs::path dir = tmp_dir();
  const int status =
      run("tir info " + file.string() + " > " + (dir / "info.txt").string(), dir / "info_err.txt");
  return {status, slurp(dir / "info.txt") + slurp(dir / "info_err.txt")};
}

// The number printed after `label` on its line.
double number_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  EXPECT_NE(at, std::string::npos) << label << " not in:\n" << text;
  if (at == std::string::npos) return 0.0;
  return std::stod(text.substr(at + label.size()));
}

TEST(TirInfoCommand, Mf61SampleShowsModelLimitsAndFigures) {
  const fs::path tir = testing::tyre_file("MagicFormula61_Parameters.tir");
  const Output r = info(tir);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("model: MF 6.1 (PROPERTY_FILE_FORMAT 'USER', FITTYP 61)"), std::string::npos)
      << r.out;
  EXPECT_NE(
      r.out.find(
          "units: LENGTH 'meter', FORCE 'newton', ANGLE 'radians', MASS 'kg', TIME 'second'\n"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("defaulted keys (0):\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warnings: none"), std::string::npos) << r.out;
  const auto p = tyre::load_mf_parameters(tir).params;
  const tyre::MfTyreFigures f = tyre::tyre_figures(p, mf::MfOptions{});
  EXPECT_NEAR(number_after(r.out, "FNOMIN: "), p.fnomin_n, 1e-9);
  EXPECT_NEAR(number_after(r.out, "peak μy: "), f.muy, 1e-3);
  EXPECT_NEAR(number_after(r.out, "peak μx: drive "), f.mux_drive, 1e-3);
  EXPECT_NEAR(number_after(r.out, "cornering stiffness Kyα: "), f.kya_nprad, 1e-5 * f.kya_nprad);
  EXPECT_NEAR(number_after(r.out, "slip stiffness Kxκ: "), f.kxk_n, 1e-5 * f.kxk_n);
}

TEST(TirInfoCommand, UnitsAreConvertedAndSaid) {
  const Output si = info(testing::tyre_file("MagicFormula61_Parameters.tir"));
  const Output mm = info(testing::test_data("tir-variants/mf61_mm_kN_deg.tir"));
  ASSERT_EQ(mm.status, 0) << mm.out;
  EXPECT_NE(mm.out.find("(values below converted to SI)"), std::string::npos) << mm.out;
  // The same tyre in other units: the same figures in SI.
  for (const char* label : {"FNOMIN: ", "R0: ", "peak μy: ", "cornering stiffness Kyα: ",
                            "pneumatic trail (α = 0.5°): "}) {
    EXPECT_NEAR(number_after(mm.out, label), number_after(si.out, label),
                1e-4 * std::fabs(number_after(si.out, label)))
        << label;
  }
}

TEST(TirInfoCommand, OtherModelsAndDefectiveFilesAreNamed) {
  Output r = info(testing::tyre_file("chrono_HMMWV_Pac89Tire.tir"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("PAC89"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tread pac eval"), std::string::npos) << r.out;
  r = info(testing::test_data("tir-variants/harty_function_name.tir"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("not a Magic Formula file"), std::string::npos) << r.out;
  r = info(testing::test_data("tir-variants/defective_zero_vertical_stiffness.tir"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("VERTICAL_STIFFNESS"), std::string::npos) << r.out;
  // A PAC2002 file is named as such.
  r = info(testing::tyre_file("chrono_Sedan_Pac02Tire.tir"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("model: PAC2002"), std::string::npos) << r.out;
}

TEST(TirConvert, UnitsSiRewritesInSiAndEvaluatesTheSame) {
  const fs::path dir = tmp_dir();
  const fs::path mm = testing::test_data("tir-variants/mf61_mm_kN_deg.tir");
  const fs::path out = dir / "mf61_si.tir";
  ASSERT_EQ(run("tir convert --units si " + mm.string() + " " + out.string(), dir / "stderr.txt"),
            0)
      << slurp(dir / "stderr.txt");
  const tir::TirFile f = tir::read_tir(out);
  EXPECT_EQ(f.text("UNITS", "LENGTH"), "meter");
  EXPECT_EQ(f.text("UNITS", "FORCE"), "newton");
  EXPECT_EQ(f.text("UNITS", "ANGLE"), "radians");
  const auto a =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params;
  const auto b = tyre::load_mf_parameters(out).params;
  EXPECT_NEAR(b.unloaded_radius_m, a.unloaded_radius_m, 1e-12);
  EXPECT_NEAR(b.fnomin_n, a.fnomin_n, 1e-9);
  EXPECT_NEAR(b.alpmax_rad, a.alpmax_rad, 1e-12);
  mf::MfInput<double> x;
  x.fz_n = 5000.0;
  x.kappa = -0.04;
  x.alpha_rad = 0.06;
  x.vx_mps = 25.0;
  const auto ra = mf::evaluate(a, x, mf::MfOptions{});
  const auto rb = mf::evaluate(b, x, mf::MfOptions{});
  EXPECT_NEAR(rb.fy_n, ra.fy_n, 1e-9 * std::fabs(ra.fy_n));
  EXPECT_NEAR(rb.mz_nm, ra.mz_nm, 1e-9 * std::fabs(ra.mz_nm));
  EXPECT_NEAR(rb.rl_m, ra.rl_m, 1e-12);
}

}  // namespace
}  // namespace tread
