// The data the project ships (data/tyres, tests/data) against the originals it was made from
// (TREAD_REFDATA_DIR, none by default; see data/PROVENANCE.md and
// scripts/import-refdata.sh): every number carried over unchanged, no third-party comment
// carried over. Without the originals beside the clone the comparisons skip with that reason; the
// checks of the shipped files themselves always run.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "profile/simpack_profile.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_file.hpp"

namespace tread {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

// Data lines: neither comments nor blank.
std::vector<std::string> data_lines(const fs::path& path) {
  std::vector<std::string> out;
  for (const std::string& l : lines_of(path)) {
    if (!l.empty() && l[0] != '#') out.push_back(l);
  }
  return out;
}

std::vector<fs::path> files_in(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ext) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ShippedData, TyreFilesCarryNoThirdPartyComments) {
  const auto tyres = files_in(testing::tyres_dir(), ".tir");
  ASSERT_GE(tyres.size(), 10u) << testing::tyres_dir();
  for (const fs::path& p : tyres) {
    const std::vector<std::string> lines = lines_of(p);
    ASSERT_FALSE(lines.empty()) << p;
    // One comment line of our own at the top; none after it (inline or whole-line).
    EXPECT_EQ(lines[0].rfind("$ ", 0), 0u) << p;
    for (std::size_t i = 1; i < lines.size(); ++i) {
      EXPECT_EQ(lines[i].find('$'), std::string::npos) << p << ":" << i + 1 << ": " << lines[i];
      EXPECT_EQ(lines[i].find('!'), std::string::npos) << p << ":" << i + 1 << ": " << lines[i];
    }
    EXPECT_NO_THROW(tir::read_tir(p)) << p;
  }
}

// Every section, key, value (as text) and table row of the original, in order.
void expect_same_tir(const tir::TirFile& original, const tir::TirFile& shipped) {
  ASSERT_EQ(original.sections().size(), shipped.sections().size()) << shipped.origin();
  for (std::size_t s = 0; s < original.sections().size(); ++s) {
    const tir::Section& a = original.sections()[s];
    const tir::Section& b = shipped.sections()[s];
    EXPECT_EQ(a.name, b.name) << shipped.origin();
    const auto ea = a.entries();
    const auto eb = b.entries();
    ASSERT_EQ(ea.size(), eb.size()) << shipped.origin() << " [" << a.name << "]";
    for (std::size_t i = 0; i < ea.size(); ++i) {
      EXPECT_EQ(ea[i]->key, eb[i]->key) << shipped.origin();
      EXPECT_EQ(ea[i]->value, eb[i]->value) << shipped.origin() << " " << ea[i]->key;
      EXPECT_EQ(ea[i]->quote, eb[i]->quote) << shipped.origin() << " " << ea[i]->key;
    }
    const auto ra = a.table_rows();
    const auto rb = b.table_rows();
    ASSERT_EQ(ra.size(), rb.size()) << shipped.origin() << " [" << a.name << "]";
    for (std::size_t i = 0; i < ra.size(); ++i) {
      // The same numbers; the shipped row is trimmed and has no trailing comment.
      const std::string& row = ra[i];
      const std::size_t c = row.find_first_of("$!");
      std::string expected = row.substr(0, c);
      expected.erase(0, expected.find_first_not_of(" \t"));
      expected.erase(expected.find_last_not_of(" \t\r") + 1);
      EXPECT_EQ(expected, rb[i]) << shipped.origin();
    }
  }
}

TEST(ShippedData, TyreFilesEqualTheOriginals) {
  const auto originals = testing::refdata_originals();
  if (!originals)
    GTEST_SKIP() << "no original reference data beside this clone (TREAD_REFDATA_DIR)";
  std::size_t compared = 0;
  for (const fs::path& p : files_in(*originals / "tir", ".tir")) {
    const fs::path shipped = testing::tyre_file(p.filename().string());
    ASSERT_TRUE(fs::exists(shipped)) << "not shipped: " << p.filename();
    expect_same_tir(tir::read_tir(p), tir::read_tir(shipped));
    ++compared;
  }
  EXPECT_GE(compared, 9u);
  // The Chrono PAC89 JSON: the same coefficients in the shipped .tir and the shipped JSON.
  const auto json = tir::pac_from_chrono_json(*originals / "tir" / "chrono_HMMWV_Pac89Tire.json");
  const auto as_tir =
      tir::pac_from_tir(tir::read_tir(testing::tyre_file("chrono_HMMWV_Pac89Tire.tir")));
  const auto as_json =
      tir::pac_from_chrono_json(testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json"));
  for (const auto* got : {&as_tir, &as_json}) {
    EXPECT_EQ(got->params.a, json.params.a);
    EXPECT_EQ(got->params.b, json.params.b);
    EXPECT_EQ(got->params.c, json.params.c);
    EXPECT_EQ(got->params.unloaded_radius_m, json.params.unloaded_radius_m);
    EXPECT_EQ(got->params.rolling_resistance, json.params.rolling_resistance);
    EXPECT_EQ(got->params.lateral_stiffness_npm, json.params.lateral_stiffness_npm);
  }
}

TEST(ShippedData, CsvTablesEqualTheOriginals) {
  const auto originals = testing::refdata_originals();
  if (!originals)
    GTEST_SKIP() << "no original reference data beside this clone (TREAD_REFDATA_DIR)";
  std::size_t compared = 0;
  for (const char* dir : {"mfeval", "rail/en13715", "rail/en15302"}) {
    for (const fs::path& p : files_in(*originals / dir, ".csv")) {
      const fs::path shipped = testing::test_data(std::string(dir) + "/" + p.filename().string());
      ASSERT_TRUE(fs::exists(shipped)) << "not shipped: " << p;
      EXPECT_EQ(data_lines(p), data_lines(shipped)) << shipped;
      // Only column-name comments are kept.
      for (const std::string& l : lines_of(shipped)) {
        if (!l.empty() && l[0] == '#') {
          EXPECT_EQ(l.find(' ', 2), std::string::npos) << shipped << ": " << l;
        }
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 12u);
}

TEST(ShippedData, BenchmarkProfilesEqualTheOriginals) {
  const auto originals = testing::refdata_originals();
  if (!originals)
    GTEST_SKIP() << "no original reference data beside this clone (TREAD_REFDATA_DIR)";
  for (const char* name : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"}) {
    const auto a =
        profile::read_simpack_profile(*originals / "rail" / "manchester_benchmark" / name);
    const auto b = profile::read_simpack_profile(
        testing::test_data(std::string("rail/manchester_benchmark/") + name));
    EXPECT_EQ(a.type, b.type) << name;
    ASSERT_EQ(a.profile.y_mm.size(), b.profile.y_mm.size()) << name;
    for (std::size_t i = 0; i < a.profile.y_mm.size(); ++i) {
      // The writer prints 13 significant digits: far below the data's own 1e-6 mm.
      EXPECT_NEAR(a.profile.y_mm[i], b.profile.y_mm[i], 1e-9) << name << " point " << i;
      EXPECT_NEAR(a.profile.z_mm[i], b.profile.z_mm[i], 1e-9) << name << " point " << i;
    }
  }
}

}  // namespace
}  // namespace tread
