#include "tir/tir_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "golden_path.hpp"

namespace {

using tread::tir::KeyDefault;
using tread::tir::Line;
using tread::tir::parse_tir;
using tread::tir::read_tir;
using tread::tir::TirError;
using tread::tir::TirFile;
using tread::tir::write_tir;

const std::array<const char*, 9> kRefFiles = {
    "MagicFormula52_Parameters.tir",
    "MagicFormula61_Parameters.tir",
    "MagicFormula62_Parameters.tir",
    "PacejkaBook_Defaults.tir",
    "chrono_Sedan_Pac02Tire.tir",
    "chrono_VW_mf_185_80R14_PAC2002.tir",
    "chrono_feda_335_65R22_5_G275MSA_60psi.tir",
    "derived_chrono_VW_mf_185_80R14_PAC2002_FITTYP6.tir",
    "reference_tire_tvd3.tir",
};

std::filesystem::path ref(const std::string& name) {
  auto p = tread::testing::tyre_file(name);
  EXPECT_TRUE(std::filesystem::exists(p)) << p << " is missing";
  return p;
}

// Expects parse_tir(text) to throw a TirError at `line` whose message contains `what`.
void expect_error(const std::string& text, int line, const std::string& what) {
  try {
    (void)parse_tir(text, "t.tir");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const TirError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.file(), "t.tir");
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("t.tir:" + std::to_string(line) + ": ", 0), 0U) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(TirFile, ParsesSectionsKeysCommentsAndQuotes) {
  const std::string text =
      "$ header comment\n"
      "! another\n"
      "[MODEL]   $ trailing on header\n"
      "FITTYP = 61 $ version\n"
      "tyreside='LEFT'\n"
      "NAME = \"with 'single' inside\" ! comment\n"
      "EMPTY = ''\n"
      "PLUS = +1.5E+03\n"
      "FORTRAN = 2.5D-3\n"
      "NEG=-7.9179e-002!c\n"
      "[dimension]\r\n"
      "UNLOADED_RADIUS = 0.3135\r\n";
  const TirFile f = parse_tir(text, "mem");
  ASSERT_EQ(f.sections().size(), 2U);
  EXPECT_EQ(f.preamble().size(), 2U);
  EXPECT_EQ(f.number("model", "fittyp"), 61.0);
  EXPECT_EQ(f.text("MODEL", "TYRESIDE"), "LEFT");
  EXPECT_EQ(f.text("MODEL", "NAME"), "with 'single' inside");
  EXPECT_EQ(f.text("MODEL", "EMPTY"), "");
  EXPECT_EQ(f.number("MODEL", "PLUS"), 1500.0);
  EXPECT_EQ(f.number("MODEL", "FORTRAN"), 2.5e-3);
  EXPECT_EQ(f.number("MODEL", "NEG"), -7.9179e-2);
  EXPECT_EQ(f.find("MODEL", "FITTYP")->comment, "$ version");
  EXPECT_EQ(f.find("MODEL", "NEG")->comment, "!c");
  EXPECT_EQ(f.number("DIMENSION", "UNLOADED_RADIUS"), 0.3135);
  EXPECT_EQ(f.number_any("unloaded_radius"), 0.3135);
  EXPECT_EQ(f.find("MODEL", "UNLOADED_RADIUS"), nullptr);
  EXPECT_FALSE(f.number("MODEL", "MISSING").has_value());
  EXPECT_FALSE(f.text_any("MISSING").has_value());
  EXPECT_EQ(f.find("MODEL", "NEG")->line, 10);
  EXPECT_EQ(f.sections()[0].entries().size(), 7U);
}

TEST(TirFile, TableSectionsKeptVerbatim) {
  const std::string text =
      "[SHAPE]\n"
      "{radial width}\n"
      " 1.0    0.0\n"
      "$ comment between rows\n"
      " 0.9    1.0\n"
      "[VERTICAL]\n"
      "FNOMIN = 4000\n";
  const TirFile f = parse_tir(text, "mem");
  const auto* shape = f.section("shape");
  ASSERT_NE(shape, nullptr);
  EXPECT_TRUE(shape->is_table());
  EXPECT_EQ(shape->table_rows(),
            (std::vector<std::string>{"{radial width}", " 1.0    0.0", " 0.9    1.0"}));
  EXPECT_FALSE(f.section("VERTICAL")->is_table());
  EXPECT_EQ(write_tir(f), text);
}

TEST(TirFile, ErrorsNameFileAndLine) {
  expect_error("[A]\nX = 'abc\n", 2, "unterminated quote");
  expect_error("[A]\nX = \"abc\n", 2, "unterminated quote");
  expect_error("$c\nX = 1\n[A]\n", 2, "outside any section");
  expect_error("1.0 2.0\n", 1, "outside any section");
  expect_error("[A]\nX = 1\nY = 2\nx = 3\n", 4, "duplicate key 'x' in [A] (first at line 2)");
  expect_error("[A]\nX = 1\n[B]\n[a]\nX = 3\n", 5, "duplicate key");
  expect_error("[A]\n(COMMENTS)\n{comment_string}\nnot quoted\n", 4, "sub-block");
  expect_error("(COMMENTS)\n[A]\n", 1, "outside any section");
  expect_error("[A]\nX = 'a' b\n", 2, "after closing quote");
  expect_error("[A\nX = 1\n", 1, "without ']'");
  expect_error("[A]\nX = 1\nY 2\n", 3, "neither 'KEY = value' nor a comment");
  expect_error("[A]\n1 2\nX = 1\n", 3, "table section");
  // A key missing its '=' before the section's entries: the error is at that line, not at the
  // well-formed entry after it.
  expect_error("[A]\nFNOMIN 6752\nX = 1\n", 2,
               "(a missing '='? entries follow at line 3): 'FNOMIN 6752'");
  // The text an error quotes: control bytes as '?', at most 80 characters and the length (a
  // 50 MB line was echoed whole).
  expect_error("[A]\nX = 1\n" + std::string(100000, 'y') + " 2\n", 3,
               "'" + std::string(80, 'y') + "… (100002 characters)'");
  expect_error("[A]\nX = 'a' b\x01\x02\n", 2,
               "after closing quote in value of 'X': 'b?"
               "?'");
  // Keys and section names no .tir has: refused with their length, not quoted whole.
  expect_error("[A]\n" + std::string(100000, 'K') + " = 1\n", 2,
               "a key of 100000 characters (a .tir key has at most 64): '" + std::string(80, 'K') +
                   "… (100000 characters)'");
  expect_error("[" + std::string(65, 'S') + "]\n", 1,
               "a section name of 65 characters (a .tir section name has at most 64)");
  EXPECT_NO_THROW(
      parse_tir("[" + std::string(64, 'S') + "]\n" + std::string(64, 'K') + " = 1\n", "x.tir"));
}

// A UTF-8 byte-order mark before the first section ("text outside any section: '[MDI_HEADER]'",
// the mark invisible) and CR-only line ends (one line of 24 kB) read as a text editor shows them.
TEST(TirFile, ByteOrderMarkAndCrOnlyLinesAreRead) {
  const TirFile bom = parse_tir("\xEF\xBB\xBF[MODEL]\nFITTYP = 61\n", "bom.tir");
  EXPECT_EQ(bom.number("MODEL", "FITTYP"), 61.0);
  EXPECT_TRUE(bom.warnings().empty());
  const TirFile cr = parse_tir("[MODEL]\rFITTYP = 61\r[VERTICAL]\rFNOMIN = 4000\r", "cr.tir");
  EXPECT_EQ(cr.number("VERTICAL", "FNOMIN"), 4000.0);
  ASSERT_EQ(cr.warnings().size(), 1U);
  EXPECT_EQ(cr.warnings()[0], "cr.tir: lines end in CR only (old Mac text): read as line ends");
}

std::filesystem::path variant(const std::string& name) {
  return std::filesystem::path(TREAD_SOURCE_DIR) / "tests/data/tir-variants" / name;
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Adams `(COMMENTS)` sub-blocks: `{comment_string}` and quoted lines parse, carry no values, and
// are written back verbatim; keys after the block are read.
TEST(TirFileVariants, AdamsCommentBlocks) {
  const auto path = variant("adams_comment_block.tir");
  const TirFile f = read_tir(path);
  EXPECT_EQ(f.text("MDI_HEADER", "FILE_FORMAT"), "ASCII");
  EXPECT_EQ(f.number("MODEL", "FITTYP"), 61.0);
  EXPECT_EQ(f.number("MODEL", "LONGVL"), 16.7);
  EXPECT_EQ(f.number("VERTICAL", "FNOMIN"), 4000.0);
  std::size_t block_lines = 0;
  for (const auto& s : f.sections()) {
    for (const auto& l : s.lines) block_lines += l.kind == Line::Kind::kBlockText ? 1U : 0U;
  }
  EXPECT_EQ(block_lines, 7U);
  EXPECT_TRUE(f.warnings().empty());
  EXPECT_EQ(write_tir(f), slurp(path));
}

// `KEY =` without a value: absent for lookups, a warning with file:line, kept for the round trip;
// set() fills the line in place.
TEST(TirFileVariants, EmptyValuesAreAbsentWithAWarning) {
  const auto path = variant("empty_values.tir");
  TirFile f = read_tir(path);
  EXPECT_EQ(f.find("MODEL", "USE_MODE"), nullptr);
  EXPECT_EQ(f.number_any("VERTICAL_DAMPING"), std::nullopt);
  EXPECT_EQ(f.number("VERTICAL", "FNOMIN"), 4000.0);
  ASSERT_EQ(f.warnings().size(), 2U);
  EXPECT_EQ(f.warnings()[0], path.string() + ":6: 'USE_MODE' has no value: treated as absent");
  EXPECT_EQ(f.warnings()[1],
            path.string() + ":9: 'VERTICAL_DAMPING' has no value: treated as absent");
  EXPECT_EQ(write_tir(f), slurp(path));
  f.set("MODEL", "USE_MODE", 14);
  const std::string written = write_tir(f);
  EXPECT_NE(written.find("FITTYP = 61\nUSE_MODE = 14\n[VERTICAL]"), std::string::npos) << written;
  const TirFile again = parse_tir(written, "again");
  EXPECT_EQ(again.number("MODEL", "USE_MODE"), 14.0);
  EXPECT_EQ(again.warnings().size(), 1U);
}

// CRLF files are written back with CRLF, byte for byte; LF files keep LF.
TEST(TirFileVariants, CrlfKeptOnRoundTrip) {
  const auto path = variant("crlf.tir");
  TirFile f = read_tir(path);
  EXPECT_EQ(f.line_ending(), "\r\n");
  EXPECT_EQ(write_tir(f), slurp(path));
  f.set("VERTICAL", "FNOMIN", 4500);
  const std::string written = write_tir(f);
  EXPECT_NE(written.find("FNOMIN = 4500\r\n"), std::string::npos);
  EXPECT_EQ(written.find("\r\r"), std::string::npos);
  EXPECT_EQ(std::count(written.begin(), written.end(), '\n'),
            std::count(written.begin(), written.end(), '\r'));
  EXPECT_EQ(parse_tir("[A]\nX = 1\n", "lf").line_ending(), "\n");
}

TEST(TirFile, NumberWhereTextIsFoundIsAnErrorWithLine) {
  const TirFile f = parse_tir("[A]\n\nX = 'text'\nY = abc\nZ = 1.0.0\n", "t.tir");
  for (const auto& [key, line] : {std::pair{"X", 3}, {"Y", 4}, {"Z", 5}}) {
    try {
      (void)f.number("A", key);
      ADD_FAILURE() << key;
    } catch (const TirError& e) {
      EXPECT_EQ(e.line(), line);
      EXPECT_NE(std::string(e.what()).find("t.tir:" + std::to_string(line) + ": value of '"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(f.text("A", "Y"), "abc");  // text access never throws
}

TEST(TirFile, MissingFileIsAnError) {
  EXPECT_THROW((void)read_tir("/nonexistent/x.tir"), TirError);
}

TEST(TirFile, ParseNumber) {
  using tread::tir::parse_number;
  EXPECT_EQ(parse_number("1e3"), 1000.0);
  EXPECT_EQ(parse_number("-.5"), -0.5);
  EXPECT_EQ(parse_number("3."), 3.0);
  EXPECT_FALSE(parse_number("nan"));
  EXPECT_FALSE(parse_number("inf"));
  EXPECT_FALSE(parse_number("1e999"));
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("0x10"));
  EXPECT_FALSE(parse_number("1 2"));
}

// Every reference file parses; spot-check values read by hand from each file.
TEST(TirFileGolden, AllReferenceFilesParse) {
  for (const char* name : kRefFiles) {
    SCOPED_TRACE(name);
    const TirFile f = read_tir(ref(name));
    EXPECT_GT(f.sections().size(), 5U);
    EXPECT_TRUE(f.number_any("UNLOADED_RADIUS").has_value());
    EXPECT_TRUE(f.number_any("FNOMIN").has_value());
    EXPECT_TRUE(f.number("LONGITUDINAL_COEFFICIENTS", "PCX1").has_value());
    // Every entry of every key/value section is either quoted text or a number (or a bare word).
    std::size_t entries = 0;
    for (const auto& s : f.sections()) entries += s.entries().size();
    EXPECT_GT(entries, 100U);
  }
  const TirFile mf61 = read_tir(ref("MagicFormula61_Parameters.tir"));
  EXPECT_EQ(mf61.number("VERTICAL", "FNOMIN"), 6752.0);
  EXPECT_EQ(mf61.number("dimension", "unloaded_radius"), 0.3943);
  EXPECT_EQ(mf61.text("MODEL", "TYRESIDE"), "RIGHT");
  const TirFile feda = read_tir(ref("chrono_feda_335_65R22_5_G275MSA_60psi.tir"));
  EXPECT_EQ(feda.number("ALIGNING_COEFFICIENTS", "QDZ1"), 7.9179e-2);
  EXPECT_EQ(feda.text("GOODYEAR", "TEST_NUMBER"), "");
  EXPECT_TRUE(feda.section("SHAPE")->is_table());
  EXPECT_EQ(feda.section("SHAPE")->table_rows().size(), 10U);
  std::size_t curves = 0;
  for (const auto& s : feda.sections())
    curves += tread::tir::iequals(s.name, "DEFLECTION_LOAD_CURVE");
  EXPECT_EQ(curves, 2U);  // the file repeats this table section; both are kept
  const TirFile sedan = read_tir(ref("chrono_Sedan_Pac02Tire.tir"));  // CRLF
  EXPECT_EQ(sedan.text("MODEL", "TYRESIDE"), "LEFT");
  EXPECT_EQ(sedan.number("DIMENSION", "UNLOADED_RADIUS"), 0.344);
  EXPECT_EQ(sedan.find("MODEL", "CONTACT_MODEL"), nullptr);  // commented out with '!'
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (const char c : s) {
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Structural equality: same sections in order, same entries (key, value, quote, comment), same
// table rows and comments.
void expect_same(const TirFile& a, const TirFile& b) {
  ASSERT_EQ(a.sections().size(), b.sections().size());
  for (std::size_t i = 0; i < a.sections().size(); ++i) {
    const auto& sa = a.sections()[i];
    const auto& sb = b.sections()[i];
    EXPECT_EQ(sa.name, sb.name);
    ASSERT_EQ(sa.lines.size(), sb.lines.size()) << sa.name;
    for (std::size_t j = 0; j < sa.lines.size(); ++j) {
      const auto& la = sa.lines[j];
      const auto& lb = sb.lines[j];
      ASSERT_EQ(la.kind, lb.kind);
      if (la.kind == Line::Kind::kEntry) {
        EXPECT_EQ(la.entry.key, lb.entry.key);
        EXPECT_EQ(la.entry.value, lb.entry.value);
        EXPECT_EQ(la.entry.quote, lb.entry.quote);
        EXPECT_EQ(la.entry.comment, lb.entry.comment);
        const auto na = tread::tir::parse_number(la.entry.value);
        const auto nb = tread::tir::parse_number(lb.entry.value);
        ASSERT_EQ(na.has_value(), nb.has_value());
        if (na) {
          EXPECT_TRUE(same_bits(*na, *nb)) << la.entry.key;
        }
      } else {
        EXPECT_EQ(la.text, lb.text);
      }
    }
  }
}

// Round trip read -> write -> read: the text is identical line by line (CRLF normalised to LF) and
// the parsed structure is identical.
TEST(TirFileGolden, RoundTripIsLossless) {
  for (const char* name : kRefFiles) {
    SCOPED_TRACE(name);
    const auto path = ref(name);
    const TirFile a = read_tir(path);
    const std::string written = write_tir(a);
    std::ifstream in(path, std::ios::binary);
    const std::string original((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    EXPECT_EQ(split_lines(written), split_lines(original));
    const TirFile b = parse_tir(written, "written");
    expect_same(a, b);
  }
}

// Modified and added values survive a round trip bit for bit, including awkward doubles.
TEST(TirFile, SetWriteReadKeepsFullPrecision) {
  // The shipped MF 6.1 tyre with a commented FNOMIN line (the shipped files carry no comments).
  std::string text;
  {
    std::ifstream in(ref("MagicFormula61_Parameters.tir"));
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("FNOMIN ", 0) == 0) line += " $Nominal wheel load";
      text += line + "\n";
    }
  }
  TirFile f = parse_tir(text, "MagicFormula61_Parameters.tir");
  ASSERT_EQ(f.find("VERTICAL", "FNOMIN")->comment, "$Nominal wheel load");
  std::mt19937_64 rng(42);
  std::vector<double> values = {
      0.1 + 0.2, 1.0 / 3.0, -2.2250738585072014e-308, 4.9e-324, 1.7976931348623157e308,
      -0.0,      6752.0};
  std::uniform_int_distribution<std::uint64_t> bits;
  while (values.size() < 200) {
    const double v = std::bit_cast<double>(bits(rng));
    if (std::isfinite(v)) values.push_back(v);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    f.set("NEW_SECTION", "K" + std::to_string(i), values[i]);
  }
  f.set("vertical", "fnomin", 1.0 / 7.0);          // existing key, other case
  f.set("VERTICAL", "MY_UNKNOWN_KEY", 2.0 / 3.0);  // new key in an existing section
  f.set_text("MODEL", "TYRESIDE", "LEFT");
  f.set_text("MODEL", "NOTE", "it's");
  EXPECT_TRUE(f.erase("MODEL", "USER_SUB_ID"));
  EXPECT_FALSE(f.erase("MODEL", "USER_SUB_ID"));

  const TirFile g = parse_tir(write_tir(f), "written");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto v = g.number("NEW_SECTION", "K" + std::to_string(i));
    ASSERT_TRUE(v.has_value());
    EXPECT_TRUE(same_bits(*v, values[i])) << values[i];
  }
  EXPECT_TRUE(same_bits(*g.number("VERTICAL", "FNOMIN"), 1.0 / 7.0));
  EXPECT_EQ(g.find("VERTICAL", "FNOMIN")->comment, "$Nominal wheel load");  // comment kept
  EXPECT_TRUE(same_bits(*g.number("VERTICAL", "MY_UNKNOWN_KEY"), 2.0 / 3.0));
  EXPECT_EQ(g.text("MODEL", "TYRESIDE"), "LEFT");
  EXPECT_EQ(g.text("MODEL", "NOTE"), "it's");
  EXPECT_FALSE(g.find("MODEL", "USER_SUB_ID"));
  expect_same(g, parse_tir(write_tir(g), "again"));
  // Section order unchanged, the new section at the end.
  EXPECT_EQ(g.sections().front().name, "MDI_HEADER");
  EXPECT_EQ(g.sections().back().name, "NEW_SECTION");
  EXPECT_THROW(f.set("A", "K", std::numeric_limits<double>::quiet_NaN()), TirError);
  EXPECT_THROW(f.set("A", "1BAD", 1.0), TirError);
  TirFile table = parse_tir("[SHAPE]\n1.0 0.0\n", "t.tir");
  EXPECT_THROW(table.set("SHAPE", "K", 1.0), TirError);  // no keys in a table section
}

TEST(TirFile, ResolveNumbersListsMissingKeys) {
  const TirFile f =
      parse_tir("[VERTICAL]\nFNOMIN = 4000\n[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\n", "x.tir");
  const std::array<KeyDefault, 4> keys = {{{"VERTICAL", "FNOMIN", 1.0},
                                           {"", "PCY1", 2.0},
                                           {"LATERAL_COEFFICIENTS", "PDY1", 0.8},
                                           {"", "QSX1", 0.0}}};
  const auto r = tread::tir::resolve_numbers(f, keys);
  EXPECT_EQ(r.values, (std::vector<double>{4000.0, 1.3, 0.8, 0.0}));
  EXPECT_EQ(r.missing, (std::vector<std::string>{"LATERAL_COEFFICIENTS.PDY1", "QSX1"}));
  EXPECT_EQ(r.warning("x.tir"),
            "x.tir: 2 keys missing, defaults used: LATERAL_COEFFICIENTS.PDY1, QSX1");
  const TirFile bad = parse_tir("[VERTICAL]\nFNOMIN = 'x'\n", "bad.tir");
  EXPECT_THROW((void)tread::tir::resolve_numbers(bad, keys), TirError);
  // An almost empty file: the first 12 of its missing keys, then how many more (200 names on one
  // line were printed before).
  std::vector<KeyDefault> many;
  std::vector<std::string> names;
  for (int i = 0; i < 20; ++i) names.push_back("K" + std::to_string(i));
  for (const std::string& n : names) many.push_back({"", n, 0.0});
  EXPECT_EQ(tread::tir::resolve_numbers(f, many).warning("x.tir"),
            "x.tir: 20 keys missing, defaults used: K0, K1, K2, K3, K4, K5, K6, K7, K8, K9, K10, "
            "K11 … and 8 more ('tread tir info' lists them all)");
}

}  // namespace

namespace {

// Random mutations of a real file (characters replaced by syntax characters, lines dropped or
// duplicated) either parse or throw TirError — never anything else — and whatever parses
// round-trips exactly.
TEST(TirFileGolden, MutatedFilesParseOrFailCleanly) {
  std::ifstream in(ref("chrono_feda_335_65R22_5_G275MSA_60psi.tir"), std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  ASSERT_FALSE(original.empty());
  std::mt19937_64 rng(7);
  const std::string alphabet = "[]='\"$!\n\r\t -+.eE0123456789AZaz_{}";
  std::uniform_int_distribution<std::size_t> pos(0, original.size() - 1);
  std::uniform_int_distribution<std::size_t> ch(0, alphabet.size() - 1);
  int parsed = 0;
  int rejected = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) text[pos(rng) % text.size()] = alphabet[ch(rng)];
    try {
      const TirFile a = parse_tir(text, "m.tir");
      const TirFile b = parse_tir(write_tir(a), "w.tir");
      expect_same(a, b);
      ++parsed;
    } catch (const TirError& err) {
      EXPECT_EQ(std::string(err.what()).rfind("m.tir:", 0), 0U) << err.what();
      ++rejected;
    }
  }
  EXPECT_GT(parsed, 0);
  EXPECT_GT(rejected, 0);
}

}  // namespace
