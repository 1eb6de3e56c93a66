#include "tir/tir_header.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

#include "generated/feda_tyre.hpp"
#include "generated/mf61_tyre.hpp"
#include "generated/odd_tyre.hpp"
#include "golden_path.hpp"
#include "tir/tir_file.hpp"
#include "tir_header_core_check.hpp"

namespace {

using tread::tir::TirFile;

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Every entry of the file is in the generated table, in order, with the bit-identical number that
// read_tir gives; every table row is there verbatim.
template <std::size_t N, std::size_t M>
void expect_matches(const TirFile& f, const tread::tir::TirEntry (&entries)[N],
                    const tread::tir::TirTableRow (&rows)[M]) {
  std::size_t i = 0;
  std::size_t r = 0;
  for (const auto& s : f.sections()) {
    for (const auto& l : s.lines) {
      if (l.kind == tread::tir::Line::Kind::kTableRow) {
        ASSERT_LT(r, M);
        EXPECT_EQ(rows[r].section, s.name);
        EXPECT_EQ(rows[r].row, l.text);
        ++r;
      }
      if (l.kind != tread::tir::Line::Kind::kEntry) continue;
      ASSERT_LT(i, N);
      const auto& g = entries[i++];
      EXPECT_EQ(g.section, s.name);
      EXPECT_EQ(g.key, l.entry.key);
      EXPECT_EQ(g.text, l.entry.value);
      const auto n = l.entry.is_quoted() ? std::nullopt : tread::tir::parse_number(l.entry.value);
      EXPECT_EQ(g.is_number, n.has_value()) << g.key;
      if (n) {
        EXPECT_TRUE(same_bits(g.number, *n)) << g.key;
      }
    }
  }
  EXPECT_EQ(i, N);
  if (r != 0) {
    EXPECT_EQ(r, M);
  }
}

TEST(TirHeader, Mf61TableMatchesReader) {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  expect_matches(tread::tir::read_tir(path), tyres::kMf61, tyres::kMf61Tables);
  EXPECT_EQ(tyres::kMf61Source, "MagicFormula61_Parameters.tir");
  EXPECT_TRUE(
      same_bits(core_check_fnomin(), *tread::tir::read_tir(path).number("VERTICAL", "FNOMIN")));
}

TEST(TirHeader, FedaTables) {
  const auto path = tread::testing::tyre_file("chrono_feda_335_65R22_5_G275MSA_60psi.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  expect_matches(tread::tir::read_tir(path), tyres::kFeda, tyres::kFedaTables);
  EXPECT_EQ(tyres::kFedaTables[0].section, "SHAPE");
  EXPECT_EQ(tyres::kFedaTables[0].row, "1.00  0.00");  // as shipped: trimmed by tread tir convert
}

TEST(TirHeader, OddValuesSurvive) {
  const TirFile f = tread::tir::read_tir(tread::testing::source_dir() / "tests" / "tir" / "data" /
                                         "odd_values.tir");
  expect_matches(f, tyres::kOdd, tyres::kOddTables);
  using tread::tir::find_entry;
  EXPECT_EQ(find_entry(tyres::kOdd, "ODD_SECTION", "BACKSLASH")->text, "C:\\tyres\\x.tir");
  EXPECT_EQ(find_entry(tyres::kOdd, "", "DQUOTE")->text, "say \"hi\"");
  EXPECT_EQ(find_entry(tyres::kOdd, "", "SQUOTE")->text, "it's");
  EXPECT_EQ(find_entry(tyres::kOdd, "", "QUESTION")->text, "?\?=");
  EXPECT_EQ(find_entry(tyres::kOdd, "", "NONASCII")->text, "Reifen 205/60 R15 – Straße");
  EXPECT_TRUE(same_bits(find_entry(tyres::kOdd, "", "NEGZERO")->number, -0.0));
  EXPECT_FALSE(find_entry(tyres::kOdd, "", "BARE")->is_number);
  EXPECT_EQ(tyres::kOddTables[0].section, "");  // placeholder row: the file has no tables
}

TEST(TirHeader, RejectsBadIdentifiers) {
  const TirFile f = tread::tir::parse_tir("[A]\nX = 1\n", "a.tir");
  EXPECT_THROW((void)tread::tir::generate_header(f, {"1bad", "ns"}), tread::tir::TirError);
  EXPECT_THROW((void)tread::tir::generate_header(f, {"ok", "a::"}), tread::tir::TirError);
  EXPECT_NO_THROW((void)tread::tir::generate_header(f, {"ok", "a::b"}));
}

}  // namespace
