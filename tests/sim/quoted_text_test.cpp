// How the host's readers quote a file's text in their errors (io/text_line.hpp: excerpt,
// quoted_list): short, whatever the file holds. Before, a 50 MB line, a binary file read as text or
// a header of a million cells reached the terminal whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fit/measurement.hpp"
#include "io/text_line.hpp"
#include "profile/profile_file.hpp"
#include "test_dir.hpp"
#include "tir/tir_file.hpp"
#include "tyre/input_table.hpp"

namespace {

using tread::host::text::excerpt;
using tread::host::text::quoted_list;

// `n` times `c`, then `tail` (appended: GCC 12 warns falsely about std::string(n, c) + "...").
std::string run_of(std::size_t n, char c, std::string_view tail = {}) {
  std::string s(n, c);
  s.append(tail);
  return s;
}

TEST(Excerpt, ShortTextIsQuotedAsItIs) {
  EXPECT_EQ(excerpt(""), "");
  EXPECT_EQ(excerpt("FNOMIN 6752"), "FNOMIN 6752");
  EXPECT_EQ(excerpt(run_of(80, 'y')), run_of(80, 'y'));
  // UTF-8 is kept: units and names in other languages.
  EXPECT_EQ(excerpt("Fz [kN] Überlast µ"), "Fz [kN] Überlast µ");
}

TEST(Excerpt, LongTextIsCutWithItsLength) {
  EXPECT_EQ(excerpt(run_of(81, 'y')), run_of(80, 'y', "… (81 characters)"));
  EXPECT_EQ(excerpt(run_of(50'000'000, 'y')), run_of(80, 'y', "… (50000000 characters)"));
  EXPECT_EQ(excerpt("abcdef", 3), "abc… (6 characters)");
  // Cut at a character, not inside one; the length counts characters, not bytes.
  EXPECT_EQ(excerpt(run_of(79, 'a', "µµ")), run_of(79, 'a', "… (81 characters)"));
}

TEST(Excerpt, ControlBytesAndBrokenUtf8AreMarked) {
  EXPECT_EQ(excerpt("a\tb"), "a\\tb");
  EXPECT_EQ(excerpt(std::string("a\x01\x1b[2Jb\x7f", 8)), "a??[2Jb?");
  EXPECT_EQ(excerpt(std::string("\0x", 2)), "?x");
  // A lone continuation byte, a truncated sequence, an overlong form, a surrogate, beyond U+10FFFF.
  EXPECT_EQ(excerpt("\x80x"), "?x");
  EXPECT_EQ(excerpt("\xC3"), "?");
  EXPECT_EQ(excerpt("\xE2\x82x"), "??x");
  EXPECT_EQ(excerpt("\xC0\xAF"), "??");
  EXPECT_EQ(excerpt("\xED\xA0\x80"), "???");
  EXPECT_EQ(excerpt("\xF4\x90\x80\x80"), "????");
  EXPECT_EQ(excerpt("\xF0\x9F\x9A\x97"), "\xF0\x9F\x9A\x97");  // a car, U+1F697
}

TEST(QuotedList, ListsAFewNamesThenHowManyMore) {
  EXPECT_EQ(quoted_list({}), "");
  EXPECT_EQ(quoted_list({"a", "b\x01"}), " 'a' 'b?'");
  std::vector<std::string> many(1000, "c");
  many[0] = run_of(200, 'x');
  EXPECT_EQ(quoted_list(many, 2), " '" + run_of(80, 'x', "… (200 characters)' 'c' … and 998 more"));
}

// The message `read` throws, "" if it returned.
std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

// What every reader's error must be for a file with a long line of text or binary bytes in it:
// one short line naming the file, with no control byte.
void expect_short(const std::string& message, const std::string& source) {
  SCOPED_TRACE(source + ": " + message.substr(0, 300));
  ASSERT_FALSE(message.empty());
  EXPECT_NE(message.find(source), std::string::npos);
  EXPECT_LT(message.size(), 400U);
  EXPECT_TRUE(std::none_of(message.begin(), message.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20U || c == 0x7F;
  }));
}

const std::string kLong = run_of(100'000, 'x', "\x01\x1b[2J");

TEST(ReaderErrors, QuoteALongLineShortly) {
  namespace fs = std::filesystem;
  const fs::path dir = tread::testing::test_dir("quoted_text_test");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
  };
  const auto profile = [&](const std::string& name, const std::string& text) {
    const fs::path path = write(name, text);
    return error_of([&] {
      (void)tread::profile::read_profile_file(path, tread::profile::ProfileRole::kWheel);
    });
  };
  // Profile files: CSV (a header, then a row), SIMPACK, MiniProf.
  expect_short(profile("long_header.csv", "y [in]," + kLong + "\n1,2\n3,4\n"), "long_header.csv");
  expect_short(profile("long_row.csv", "y_mm,z_mm\n1,2\n" + kLong + ",3\n"), "long_row.csv");
  expect_short(profile("long_cell.csv", "y_mm,z_mm\n1,2\n3," + kLong + "\n"), "long_cell.csv");
  expect_short(profile("long_unit.csv", "y [" + kLong + "],z_mm\n1,2\n3,4\n"), "long_unit.csv");
  expect_short(profile("long.prw", "header.begin\n  " + kLong + "\nheader.end\n"), "long.prw");
  expect_short(profile("long_point.prw",
                       "header.begin\n  type = 1\nheader.end\nspline.begin\n  point.begin\n"
                       "    1 2\n    " +
                           kLong + "\n  point.end\nspline.end\n"),
               "long_point.prw");
  expect_short(profile("long.whl", "XOffset=" + kLong + "\n\n1 2\n3 4\n"), "long.whl");
  expect_short(profile("long_point.whl", "Points=2\n\n1 2\n" + kLong + "\n"), "long_point.whl");

  // Measurements: a CSV cell, a CSV unit, a TYDEX unit and value.
  const auto measurement_csv = [](const std::string& text) {
    std::istringstream in(text);
    return error_of([&] { (void)tread::fit::read_measurement_csv(in, "m.csv"); });
  };
  expect_short(measurement_csv("Fz_N,kappa,Fx_N\n4000,0.01," + kLong + "\n"), "m.csv");
  expect_short(measurement_csv("Fz_" + kLong + ",kappa,Fx_N\n4000,0.01,100\n"), "m.csv");
  expect_short(measurement_csv("Fz [" + kLong + "],kappa,Fx_N\n4000,0.01,100\n"), "m.csv");
  const auto tydex = [](const std::string& text) {
    std::istringstream in(text);
    return error_of([&] { (void)tread::fit::read_tydex(in, "m.tdx"); });
  };
  const std::string channels = "**MEASURCHANNELS\nFZW load N 1 0 0\nFXW force N 1 0 0\n";
  expect_short(tydex("**MEASURCHANNELS\nFZW load " + kLong + " 1 0 0\n"), "m.tdx");
  expect_short(tydex(channels + "**MEASURDATA\n4000 " + kLong + "\n"), "m.tdx");

  // `tread mf eval`'s input table: a cell, a unit.
  const auto table = [](const std::string& text) {
    std::istringstream in(text);
    tread::tyre::InputTableOptions options;
    options.required = {tread::tyre::InputQuantity::fz};
    return error_of([&] {
      tread::tyre::InputTable t(in, "in.csv", options);
      while (t.next()) {
      }
    });
  };
  expect_short(table("Fz_N,kappa\n4000," + kLong + "\n"), "in.csv");
  expect_short(table("Fz [" + kLong + "],kappa\n4000,0\n"), "in.csv");

  // .tir: a line outside any key, a unit in [UNITS], a value that is no number.
  const auto tir = [](const std::string& text) {
    return error_of([&] { (void)tread::tir::parse_tir(text, "t.tir"); });
  };
  expect_short(tir("[A]\nX = 1\n" + kLong + "\n"), "t.tir");
  expect_short(tir("[" + kLong + "]\n"), "t.tir");
}

}  // namespace
