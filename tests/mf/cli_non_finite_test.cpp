// End to end: `tread mf eval` and `tread pac eval` (the built CLI) on defective .tir files (zero
// vertical stiffness, zero BREFF/DREFF/FREFF, zero FNOMIN, zero radius, ...) and on CSVs with
// NaN, inf, huge and empty cells. Each run either fails with an error on stderr and a non-zero
// exit status, or exits 0 with rows in which no value is NaN or inf under status "ok".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "test_dir.hpp"

namespace {

namespace fs = std::filesystem;

/// This test's own directory (CTest runs the tests of this file in parallel).
fs::path tmp_dir() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return tread::testing::test_dir(std::string("cli_non_finite_test_") + test->name());
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int run(const std::string& args, const fs::path& stderr_file) {
  const std::string command =
      std::string(TREAD_CLI) + " " + args + " > /dev/null 2> " + stderr_file.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}

bool finite_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(v);
}

/// Counts the rows of an output CSV by status; a row with a value that is not a finite number
/// under status "ok" is a failure.
struct Rows {
  int ok = 0;
  int not_ok = 0;
};
Rows check_output(const fs::path& csv, const std::string& what) {
  std::ifstream in(csv);
  std::string line;
  Rows rows;
  // Skip the leading '#' lines (the axes note), then the header.
  bool have_header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '#') {
      have_header = true;
      break;
    }
  }
  if (!have_header) {
    ADD_FAILURE() << what << ": no header in " << csv;
    return rows;
  }
  const std::vector<std::string> header = split(line);
  EXPECT_EQ(header.back(), "status") << what;
  for (int n = 2; std::getline(in, line); ++n) {
    const std::vector<std::string> cells = split(line);
    EXPECT_EQ(cells.size(), header.size()) << what << " line " << n;
    const std::string& status = cells.back();
    bool all_finite = true;
    for (std::size_t i = 0; i + 1 < cells.size(); ++i) {
      if (!finite_number(cells[i])) {
        all_finite = false;
        ADD_FAILURE() << what << " line " << n << ": " << header[i] << " = '" << cells[i]
                      << "' (status " << status << ")";
      }
    }
    if (status == "ok") {
      ++rows.ok;
      EXPECT_TRUE(all_finite) << what << " line " << n;
    } else {
      ++rows.not_ok;
    }
  }
  return rows;
}

/// Runs `args` writing `out`: a failure must say something on stderr; a success must write an
/// output with no non-finite value under "ok".
void expect_safe(const std::string& args, const fs::path& out, const std::string& what,
                 Rows* rows = nullptr) {
  fs::remove(out);
  const fs::path err = tmp_dir() / "stderr.txt";
  const int status = run(args + " --output " + out.string(), err);
  if (status != 0) {
    EXPECT_NE(slurp(err).find("error"), std::string::npos) << what << ": " << slurp(err);
    return;
  }
  const Rows r = check_output(out, what);
  if (rows != nullptr) {
    rows->ok += r.ok;
    rows->not_ok += r.not_ok;
  }
}

/// A copy of a reference .tir with each key set to `value` on its line; empty when the file does
/// not have one of the keys (the MF 5.2 file has no NOMPRES, Q_FZ2).
fs::path defective_tir(const std::string& file, const std::vector<std::string>& keys,
                       const std::string& value) {
  const std::string text = slurp(tread::testing::tyre_file(file));
  std::string out = text;
  for (const std::string& key : keys) {
    // "\nKEY   =   value   $comment": the value token is replaced.
    std::size_t at = out.find("\n" + key + " ");
    if (at == std::string::npos) at = out.find("\n" + key + "=");
    if (at == std::string::npos) return {};
    const std::size_t eq = out.find('=', at);
    const std::size_t begin = out.find_first_not_of(" \t", eq + 1);
    const std::size_t end = out.find_first_of(" \t\r\n", begin);
    out.replace(begin, end - begin, value);
  }
  std::string name = file.substr(0, file.size() - 4);
  for (const std::string& key : keys) name += "_" + key;
  const fs::path path = tmp_dir() / (name + "_" + value + ".tir");
  std::ofstream(path) << out;
  return path;
}

fs::path write_csv(const std::string& name, const std::string& text) {
  const fs::path path = tmp_dir() / name;
  std::ofstream(path) << text;
  return path;
}

const char* const kRows =
    "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps\n"
    "5000,0.05,0.05,0.02,16.7\n"
    "0,0,0,0,16.7\n"
    "25000,-0.3,-0.2,-0.05,30\n"
    "1e300,1e300,-1e300,1e300,1e300\n"
    "-1e300,-1e300,1e-300,-1e-300,0\n"
    "5000,0.05,0.05,0.02,0\n";

TEST(CliNonFinite, MfEvalOnDefectiveTirFiles) {
  const fs::path in = write_csv("rows.csv", kRows);
  Rows rows;
  int files = 0;
  for (const char* file : {"MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                           "MagicFormula52_Parameters.tir"}) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> defects = {
        {{"VERTICAL_STIFFNESS"}, "0"},
        {{"BREFF", "DREFF", "FREFF"}, "0"},
        {{"FNOMIN"}, "0"},
        {{"UNLOADED_RADIUS"}, "0"},
        {{"LONGVL"}, "0"},
        {{"NOMPRES"}, "0"},
        {{"Q_FZ2"}, "-1e6"},
        {{"PCY1"}, "1e300"},
        {{"VERTICAL_STIFFNESS"}, "-1e300"}};
    for (const auto& [keys, value] : defects) {
      const fs::path tir = defective_tir(file, keys, value);
      if (tir.empty()) continue;
      ++files;
      for (const char* mode : {"111", "212"}) {
        for (const char* precision : {"", " --float"}) {
          const std::string what = tir.filename().string() + " mode " + mode + precision;
          expect_safe(std::string("mf eval --tir ") + tir.string() + " --mode " + mode + precision +
                          " --input " + in.string(),
                      tmp_dir() / "out.csv", what, &rows);
        }
      }
    }
  }
  EXPECT_GE(files, 25);
  // Some defective files were evaluated and said so in the status column.
  EXPECT_GT(rows.not_ok, 0);
}

TEST(CliNonFinite, MfEvalOnBadCells) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  for (const char* cell : {"nan", "NaN", "inf", "-inf", "1e400", "", " ", "0x1p99999"}) {
    const fs::path in = write_csv("cells.csv", std::string("Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps\n"
                                                           "5000,0.05,") +
                                                   cell + ",0,16.7\n");
    for (const char* precision : {"", " --float"}) {
      const fs::path err = tmp_dir() / "stderr.txt";
      const int status = run("mf eval --tir " + tir.string() + precision + " --input " +
                                 in.string() + " --output " + (tmp_dir() / "out.csv").string(),
                             err);
      // A cell that is not a finite number is an error naming the file and line.
      EXPECT_NE(status, 0) << "cell '" << cell << "'";
      EXPECT_NE(slurp(err).find("cells.csv:2"), std::string::npos) << slurp(err);
    }
  }
}

/// A PAC89 property file with the symmetric test set's coefficients (tests/pac/pac_test_sets.hpp),
/// one of them replaced.
fs::path pac_tir(const std::string& name, int b2_exponent) {
  std::ostringstream t;
  t << "[MDI_HEADER]\nFILE_TYPE = 'tir'\nFILE_VERSION = 3.0\nFILE_FORMAT = 'ASCII'\n"
    << "[MODEL]\nPROPERTY_FILE_FORMAT = 'PAC89'\n"
    << "[DIMENSION]\nUNLOADED_RADIUS = 0.4\n"
    << "[PARAMETER]\nLATERAL_STIFFNESS = 200000\nROLLING_RESISTANCE = 0.015\n";
  const double a[18] = {1.3, 0, 900, 1500, 5, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double b[14] = {1.6, 0, 1000, 0, 200, 0, 0, 0, 0.3, 0, 0, 0, 0, 0};
  const double c[21] = {2.4, -2, 30, -1, -5, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  t << "[LATERAL_COEFFICIENTS]\n";
  for (int i = 0; i < 18; ++i) t << 'A' << i << " = " << a[i] << '\n';
  t << "[LONGITUDINAL_COEFFICIENTS]\n";
  for (int i = 0; i < 14; ++i) {
    t << 'B' << i << " = ";
    if (i == 2 && b2_exponent != 0) {
      t << "1e" << b2_exponent << '\n';
    } else {
      t << b[i] << '\n';
    }
  }
  t << "[ALIGNING_COEFFICIENTS]\n";
  for (int i = 0; i < 21; ++i) t << 'C' << i << " = " << c[i] << '\n';
  const fs::path path = tmp_dir() / name;
  std::ofstream(path) << t.str();
  return path;
}

TEST(CliNonFinite, PacEvalOnOverflowingCoefficients) {
  const fs::path in = write_csv("pac_rows.csv", kRows);
  Rows sound;
  const fs::path good = pac_tir("pac_sound.tir", 0);
  for (const char* model : {"89", "94"}) {
    expect_safe("pac eval --tir " + good.string() + " --model " + model + " --input " + in.string(),
                tmp_dir() / "pac_out.csv", std::string("sound PAC") + model, &sound);
  }
  EXPECT_GT(sound.ok, 0);
  // B2 = 1e300 (double) and 1e38 (float): D = (B1 Fz + B2)·Fz overflows.
  Rows rows;
  for (const int exponent : {300, 38}) {
    const fs::path tir = pac_tir("pac_b2_1e" + std::to_string(exponent) + ".tir", exponent);
    for (const char* model : {"89", "94"}) {
      for (const char* flags : {"", " --float", " --pure", " --iso-w --float"}) {
        expect_safe("pac eval --tir " + tir.string() + " --model " + model + flags + " --input " +
                        in.string(),
                    tmp_dir() / "pac_out.csv", tir.filename().string() + " PAC" + model + flags,
                    &rows);
      }
    }
  }
  EXPECT_GT(rows.not_ok, 0);
}

TEST(CliNonFinite, PacEvalOnBadCells) {
  const fs::path tir = pac_tir("pac_cells.tir", 0);
  for (const char* cell : {"nan", "inf", "-inf", "1e400", ""}) {
    const fs::path in = write_csv("pac_cells.csv", std::string("Fz_N,kappa,alpha_rad,gamma_rad\n"
                                                               "5000,0.05,") +
                                                       cell + ",0\n");
    const fs::path err = tmp_dir() / "stderr.txt";
    const int status = run("pac eval --tir " + tir.string() + " --input " + in.string() +
                               " --output " + (tmp_dir() / "pac_out.csv").string(),
                           err);
    EXPECT_NE(status, 0) << "cell '" << cell << "'";
    EXPECT_NE(slurp(err).find("pac_cells.csv:2"), std::string::npos) << slurp(err);
  }
}

}  // namespace
