// tyre::InputTable (sim/tyre/input_table.hpp): measurement column names and their units, separators,
// decimal commas, the sign conventions, and errors naming file and line. Also host::ReplaceFile.
#include "tyre/input_table.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "io/csv_number.hpp"
#include "io/replace_file.hpp"
#include "io/text_line.hpp"
#include "test_dir.hpp"
#include "tir/tir_file.hpp"

namespace {

using tread::tyre::InputQuantity;
using tread::tyre::InputTable;
using tread::tyre::InputTableOptions;
using tread::tyre::SignConvention;

constexpr double kDeg = std::numbers::pi / 180.0;

void expect_error(const std::string& text, int line, const std::string& what);

TEST(InputTable, SiNamesAreReadAsTheyAre) {
  std::istringstream in(
      "# comment\nFz_N,kappa,alpha_rad,gamma_rad,Vx_mps,phit_1pm,P_Pa\n\n"
      "4000,0.1,0.05,-0.01,16.7,0.5,200000\n");
  InputTable t(in, "si.csv", {});
  EXPECT_TRUE(t.ignored_columns().empty());
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_EQ(row->line, 4);
  EXPECT_EQ((*row)[InputQuantity::fz], 4000.0);
  EXPECT_EQ((*row)[InputQuantity::kappa], 0.1);
  EXPECT_EQ((*row)[InputQuantity::alpha], 0.05);
  EXPECT_EQ((*row)[InputQuantity::gamma], -0.01);
  EXPECT_EQ((*row)[InputQuantity::vx], 16.7);
  EXPECT_EQ((*row)[InputQuantity::phit], 0.5);
  EXPECT_EQ((*row)[InputQuantity::pressure], 200000.0);
  EXPECT_FALSE(t.next());
}

// Header cells in double quotes, as spreadsheets export text: "missing column 'Fz_N'" was said of
// a header that had it.
TEST(InputTable, QuotedHeaderCellsAreTheirNames) {
  std::istringstream in("\"Fz_N\",\"kappa\", \"alpha_deg\" \n4000,0.1,2\n");
  InputTableOptions options;
  options.required = {InputQuantity::fz, InputQuantity::kappa};
  InputTable t(in, "quoted.csv", options);
  EXPECT_TRUE(t.ignored_columns().empty());
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_EQ((*row)[InputQuantity::fz], 4000.0);
  EXPECT_NEAR((*row)[InputQuantity::alpha], 2.0 * 3.141592653589793 / 180.0, 1e-15);
}

TEST(InputTable, TtcNamesSemicolonDecimalCommaAndSaeSigns) {
  // FSAE TTC style: SAE axes (the load negative), degrees, km/h, kPa; ';' with decimal commas.
  std::istringstream in("ET;FZ;SA;SL;IA;V;P\n1,5;-1100;-3,5;0,02;2;40;82,7\n");
  InputTableOptions o;
  o.convention = SignConvention::sae;
  InputTable t(in, "ttc.dat", o);
  EXPECT_EQ(t.separator(), ';');
  ASSERT_EQ(t.ignored_columns().size(), 1U);
  EXPECT_EQ(t.ignored_columns()[0], "ET");
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::fz], 1100.0);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::alpha], 3.5 * kDeg);  // SAE α changes sign
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::kappa], 0.02);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::gamma], 2.0 * kDeg);  // an angle about x: unchanged
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::vx], 40.0 / 3.6);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::pressure], 82700.0);
  // The mapping names each column, its unit conversion and the sign change.
  std::string mapping;
  for (const auto& m : t.mapping()) mapping += m + "\n";
  EXPECT_NE(mapping.find("'SA' → alpha_rad (deg → rad, sign changed from sae to ISO-W)"),
            std::string::npos)
      << mapping;
  EXPECT_NE(mapping.find("'V' → Vx_mps (km/h → m/s)"), std::string::npos) << mapping;
  EXPECT_NE(mapping.find("'FZ' → Fz_N (in N, sign changed"), std::string::npos) << mapping;
}

// A first row whose every number has a decimal comma is a row, not a units row (it used to be
// refused as "unit '4000,5' of column 'Fz_N' is not a unit of Fz_N").
TEST(InputTable, FirstRowOfDecimalCommasIsData) {
  std::istringstream in("Fz_N;kappa;alpha_rad;gamma_rad;Vx_mps\n4000,5;0,05;0,1;0,01;16,5\n");
  InputTable t(in, "comma.csv", {});
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_EQ(row->line, 2);
  EXPECT_EQ((*row)[InputQuantity::fz], 4000.5);
  EXPECT_EQ((*row)[InputQuantity::vx], 16.5);
}

TEST(InputTable, CaseInsensitiveUnitsInNamesAndTabs) {
  std::istringstream in(
      "FZ_kN\tKappa_PCT\tAlpha_Deg\tgamma_DEG\tvx_KPH\tp_psi\n4.5\t-5\t2\t-1\t36\t30\n");
  InputTable t(in, "tabs.txt", {});
  EXPECT_EQ(t.separator(), '\t');
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::fz], 4500.0);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::kappa], -0.05);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::alpha], 2.0 * kDeg);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::gamma], -1.0 * kDeg);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::vx], 10.0);
  EXPECT_NEAR((*row)[InputQuantity::pressure], 206842.7, 0.1);  // 30 psi
  std::istringstream bar("Fz,SL,SA,IA,Vx,P_bar\n1,0,0,0,1,2.2\n");
  InputTable tb(bar, "bar.csv", {});
  EXPECT_DOUBLE_EQ((*tb.next())[InputQuantity::pressure], 220000.0);
}

TEST(InputTable, HelpListsEveryNameByUnit) {
  const std::string help = tread::tyre::input_column_help();
  for (const char* group : {"Fz_N|FZ|FZW|Load_N [N], Fz_kN [kN]", "alpha_deg|SA|SA_deg [deg]",
                            "Vx_kph|Vx_kmh|V|V_kph|V_kmh [km/h]", "P_kPa|P [kPa]", "P_psi [psi]"}) {
    EXPECT_NE(help.find(group), std::string::npos) << group << "\n" << help;
  }
  // Every name in the help is recognised.
  std::string name;
  for (char c : help + ";") {
    if (c == '|' || c == ' ' || c == ';' || c == ',') {
      if (!name.empty() && name.front() != '[') {
        EXPECT_TRUE(tread::tyre::recognise_input_column(name)) << name;
      }
      name.clear();
    } else {
      name += c;
    }
  }
}

TEST(InputTable, Utf8ByteOrderMarkBeforeTheHeader) {
  std::istringstream in(
      "\xEF\xBB\xBF"
      "FZ,SL,SA,IA,V\n1000,0,1,0,36\n");
  InputTable t(in, "excel.csv", {});
  EXPECT_TRUE(t.ignored_columns().empty());
  EXPECT_EQ(t.column_name(InputQuantity::fz), "FZ");
  EXPECT_DOUBLE_EQ((*t.next())[InputQuantity::fz], 1000.0);
}

// The line under the header names the units (FSAE TTC run files): they override the units the
// names imply; an unknown unit is an error naming the line.
TEST(InputTable, UnitsRow) {
  std::istringstream in(
      "ET\tV\tSA\tIA\tP\tFZ\tSL\ns\tmph\t[rad]\tdeg\tpsi\tlbf\tunitless\n"
      "0.1\t25\t0.1\t2\t12\t-200\t0.05\n");
  InputTable t(in, "ttc.dat", {});
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_EQ(row->line, 3);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::vx], 25 * 0.44704);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::alpha], 0.1);  // [rad] overrides SA's degrees
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::gamma], 2 * kDeg);
  EXPECT_NEAR((*row)[InputQuantity::pressure], 82737.1, 0.1);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::fz], -200 * 4.4482216152605);
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::kappa], 0.05);
  EXPECT_FALSE(t.next());
  std::string mapping;
  for (const auto& m : t.mapping()) mapping += m + "\n";
  EXPECT_NE(mapping.find("'V' → Vx_mps (mph → m/s)"), std::string::npos) << mapping;
  EXPECT_NE(mapping.find("'SA' → alpha_rad (in rad)"), std::string::npos) << mapping;
  // Only the first data row can be a units row; a unit foreign to its column is an error.
  expect_error("FZ,SL,SA,IA,V\nN,1,deg,deg,furlong/fortnight\n", 2,
               "unit 'furlong/fortnight' of column 'V' is not a unit of Vx_mps");
  expect_error("FZ,SL,SA,IA,V\n1,0,0,0,1\nN,1,deg,deg,kph\n", 3, "FZ: 'N' is not a finite number");
}

TEST(InputTable, ExplicitSeparatorAndAdaptedIso) {
  std::istringstream in("Fz_N;kappa;alpha_rad;gamma_rad;Vx_mps\n4000;0.1;0.05;0.02;10\n");
  InputTableOptions o;
  o.separator = ';';
  o.convention = SignConvention::adapted_iso;
  InputTable t(in, "x.csv", o);
  const auto row = t.next();
  ASSERT_TRUE(row);
  EXPECT_EQ((*row)[InputQuantity::alpha], -0.05);
  EXPECT_EQ((*row)[InputQuantity::gamma], 0.02);
  EXPECT_EQ((*row)[InputQuantity::fz], 4000.0);
}

TEST(InputTable, ConventionsAndOutputSigns) {
  using tread::tyre::MeasuredQuantity;
  using tread::tyre::output_sign;
  EXPECT_EQ(tread::tyre::parse_sign_convention("SAE"), SignConvention::sae);
  EXPECT_EQ(tread::tyre::parse_sign_convention("iso-w"), SignConvention::iso_w);
  EXPECT_EQ(tread::tyre::parse_sign_convention("adapted-iso"), SignConvention::adapted_iso);
  EXPECT_FALSE(tread::tyre::parse_sign_convention("iso-c"));
  for (auto q : {MeasuredQuantity::fx, MeasuredQuantity::fy, MeasuredQuantity::fz,
                 MeasuredQuantity::mx, MeasuredQuantity::my, MeasuredQuantity::mz}) {
    EXPECT_EQ(output_sign(SignConvention::iso_w, q), 1.0);
  }
  EXPECT_EQ(output_sign(SignConvention::sae, MeasuredQuantity::fx), 1.0);
  EXPECT_EQ(output_sign(SignConvention::sae, MeasuredQuantity::fy), -1.0);
  EXPECT_EQ(output_sign(SignConvention::sae, MeasuredQuantity::fz), -1.0);
  EXPECT_EQ(output_sign(SignConvention::sae, MeasuredQuantity::mx), 1.0);
  EXPECT_EQ(output_sign(SignConvention::sae, MeasuredQuantity::mz), -1.0);
  EXPECT_EQ(output_sign(SignConvention::adapted_iso, MeasuredQuantity::fy), -1.0);
  EXPECT_EQ(output_sign(SignConvention::adapted_iso, MeasuredQuantity::fz), 1.0);
  // The turn slip is a yaw rate over the speed: a rotation about z, which SAE's z (down) reverses;
  // adapted ISO keeps ISO-W's axes.
  EXPECT_EQ(iso_w_sign(SignConvention::sae, InputQuantity::phit), -1.0);
  EXPECT_EQ(iso_w_sign(SignConvention::adapted_iso, InputQuantity::phit), 1.0);
  EXPECT_EQ(iso_w_sign(SignConvention::sae, InputQuantity::gamma), 1.0);
  EXPECT_EQ(iso_w_sign(SignConvention::sae, InputQuantity::kappa), 1.0);
}

void expect_error(const std::string& text, int line, const std::string& what) {
  std::istringstream in(text);
  try {
    InputTable t(in, "bad.csv", {});
    while (t.next()) {
    }
    ADD_FAILURE() << text;
  } catch (const tread::tir::TirError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.csv:" + std::to_string(line)), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(InputTable, ErrorsNameFileAndLine) {
  expect_error("", 0, "no header row");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad\n", 1, "missing column 'Vx_mps'");
  expect_error("FZ,SL,SA,alpha_deg,IA,V\n", 1, "'SA' and 'alpha_deg' both give alpha_rad");
  expect_error("FZ,SL,SA,IA,V\n1,2,3,4,5\n\n1,2,3,4\n", 4, "expected 5 cells, found 4");
  expect_error("FZ,SL,SA,IA,V\n1,2,3,deg,5\n", 2, "IA: 'deg' is not a finite number");
  expect_error("FZ,SL,SA,IA,V\n1,2,inf,0,5\n", 2, "SA: 'inf' is not a finite number");
  // A ',' file does not take decimal commas: the cell count is wrong instead.
  expect_error("FZ,SL,SA,IA,V\n1,0,5,2,0,5\n", 2, "expected 5 cells, found 6");
  // A decimal comma and a point in one row: "4.000" may be 4000 (a thousands separator).
  expect_error("FZ;SL;SA;IA;V\n4.000;0,05;0;0;16\n", 2,
               "'0,05' has a decimal comma and '4.000' a point: with both in one row the point "
               "may be a thousands separator; write every number with one decimal separator");
  // Finite as written, infinite in SI units: an error, not an inf input (either reader).
  expect_error("Fz_kN,SL,SA,IA,V\n1e308,0,0,0,5\n", 2,
               "Fz_kN: '1e308' is out of range once converted to SI units");
  expect_error("Fz_kN;SL;SA;IA;V\n1e308;0;0;0;5\n", 2,
               "Fz_kN: '1e308' is out of range once converted to SI units");
}

// With InputTableOptions::measured the fitter's measured columns are read too (empty: NaN);
// without it they are ignored columns.
TEST(InputTable, MeasuredColumnsOnlyWhenAsked) {
  const std::string text = "FZ,SL,SA,IA,V,FY,Mz_kNm\n1000,0,1,0,40,-500,\n";
  {
    std::istringstream in(text);
    InputTable table(in, "m.csv", InputTableOptions{});
    EXPECT_EQ(table.ignored_columns(), (std::vector<std::string>{"FY", "Mz_kNm"}));
  }
  std::istringstream in(text);
  InputTableOptions options;
  options.convention = SignConvention::sae;
  options.measured = true;
  InputTable table(in, "m.csv", options);
  EXPECT_TRUE(table.ignored_columns().empty());
  EXPECT_TRUE(table.has(tread::tyre::MeasuredQuantity::fy));
  tread::tyre::MeasuredValues measured{};
  const auto row = table.next(&measured);
  ASSERT_TRUE(row.has_value());
  EXPECT_DOUBLE_EQ((*row)[InputQuantity::fz], -1000.0);
  EXPECT_DOUBLE_EQ(measured[static_cast<std::size_t>(tread::tyre::MeasuredQuantity::fy)], 500.0);
  EXPECT_TRUE(std::isnan(measured[static_cast<std::size_t>(tread::tyre::MeasuredQuantity::mz)]));
  EXPECT_TRUE(std::isnan(measured[static_cast<std::size_t>(tread::tyre::MeasuredQuantity::fx)]));
  const std::vector<std::string> map = table.mapping();
  EXPECT_EQ(map.back(), "'Mz_kNm' → Mz_Nm (kN m → N m, sign changed from sae to ISO-W)");
}

// A ',' row is read in one pass (InputTable::read_comma_row) and, where that declines, cell by
// cell: whichever reads it, each cell's value is read_csv_number's of the trimmed cell, to the
// bit, and a cell it refuses is an error naming its column and text. The cell stands first, after
// an ignored column, and last.
TEST(InputTable, CommaRowsGiveEachCellsOwnValueOrItsError) {
  const std::string long_zeros = "0." + std::string(61, '0') + "1";  // 64 characters
  const std::string cells[] = {"4000",
                               " 4000 ",
                               "\t+4.5e3\r",
                               "\v7\f",
                               "\f-2.5\v",
                               "-0",
                               "0",
                               "0.000",
                               "0e5",
                               "-0.0e-9",
                               "1e-300",
                               "1e-320",
                               "1e-400",
                               "0.0e-400",
                               "1.5D-3",
                               " 1.5d+2 ",
                               "2.5E+02",
                               ".5",
                               "5.",
                               "-.5e1",
                               long_zeros,
                               long_zeros + "2",
                               "+-5",
                               "++5",
                               "+ 5",
                               "5 5",
                               "5e",
                               "5e+",
                               "0x10",
                               "inf",
                               "-nan",
                               "1e400",
                               "",
                               "  ",
                               "1.7976931348623157e308",
                               "4.9e-324",
                               "12345678901234567890123",
                               "5x",
                               "1.5.2",
                               "\v"};
  struct Layout {
    const char* header;
    const char* before;  ///< the cells before Fz's
    const char* after;   ///< the cells after it
  };
  const Layout layouts[] = {
      {"Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps", "", ",0.1,0.02,0,16.7"},
      {"t,Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps", "1;2 x,", ",0.1,0.02,0,16.7"},
      {"kappa,alpha_rad,gamma_rad,Vx_mps,Fz_N", "0.1,0.02,0,16.7,", ""}};
  for (const std::string& cell : cells) {
    for (const Layout& layout : layouts) {
      std::istringstream in(std::string(layout.header) + "\n" + layout.before + cell +
                            layout.after + "\n");
      InputTable t(in, "cells.csv", {});
      double expected = 0.0;
      const bool number =
          tread::host::read_csv_number(tread::host::text::trim_blanks(cell), false, expected);
      if (number) {
        const auto row = t.next();
        ASSERT_TRUE(row) << cell;
        EXPECT_EQ(std::bit_cast<std::uint64_t>((*row)[InputQuantity::fz]),
                  std::bit_cast<std::uint64_t>(expected))
            << "'" << cell << "': " << (*row)[InputQuantity::fz] << " against " << expected;
        EXPECT_EQ((*row)[InputQuantity::kappa], 0.1);
        EXPECT_EQ((*row)[InputQuantity::vx], 16.7);
      } else {
        try {
          (void)t.next();
          ADD_FAILURE() << "'" << cell << "' was read";
        } catch (const tread::tir::TirError& e) {
          const std::string what = e.what();
          EXPECT_NE(what.find("cells.csv:2"), std::string::npos) << what;
          EXPECT_NE(what.find("Fz_N: '" + std::string(tread::host::text::trim_blanks(cell)) + "'"),
                    std::string::npos)
              << what;
        }
      }
    }
  }
}

// Rows of the wrong shape are errors of their cell count, whether the bad part is at the start,
// the end or in a column not read; a column not read may hold anything but a separator.
TEST(InputTable, CommaRowsOfTheWrongShape) {
  const std::string header = "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,note\n";
  {
    std::istringstream in(header + "4000,0.1,0.02,0,16.7, any text; 1e400 \t\n" +
                          " 4000 ,\t0.1\v,0.02 , 0 ,16.7,\n");
    InputTable t(in, "shape.csv", {});
    for (int line = 2; line <= 3; ++line) {
      const auto row = t.next();
      ASSERT_TRUE(row) << line;
      EXPECT_EQ(row->line, line);
      EXPECT_EQ((*row)[InputQuantity::fz], 4000.0);
      EXPECT_EQ((*row)[InputQuantity::kappa], 0.1);
      EXPECT_EQ((*row)[InputQuantity::vx], 16.7);
    }
    EXPECT_FALSE(t.next());
  }
  expect_error(header + "4000,0.1,0.02,0,16.7,a,b\n", 2, "expected 6 cells, found 7");
  expect_error(header + "4000,0.1,0.02,0,16.7,a,\n", 2, "expected 6 cells, found 7");
  expect_error(header + ",4000,0.1,0.02,0,16.7,x\n", 2, "expected 6 cells, found 7");
  expect_error(header + ",4000,0.1,0.02,0,16.7\n", 2, "Fz_N: '' is not a finite number");
  expect_error(header + "4000,0.1,0.02,0,16.7\n", 2, "expected 6 cells, found 5");
  expect_error(header + "4000,0.1,0.02,0\n", 2, "expected 6 cells, found 4");
  expect_error(header + "4000,0.1,,0,16.7,x\n", 2, "alpha_rad: '' is not a finite number");
}

TEST(ReplaceFile, CommitReplacesAndAbandonLeavesTheOldFile) {
  const auto dir = tread::testing::test_dir("replace_file_test");
  const auto target = dir / "out.csv";
  { std::ofstream(target) << "old\n"; }
  {
    tread::host::ReplaceFile f(target);
    f.stream() << "half";
    EXPECT_TRUE(std::filesystem::exists(f.temporary()));
    // no commit: as if an exception left the scope
  }
  {
    std::ifstream in(target);
    std::string s;
    std::getline(in, s);
    EXPECT_EQ(s, "old");
  }
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename(), "out.csv") << "left behind: " << e.path();
  }
  {
    tread::host::ReplaceFile f(target);
    f.stream() << "new\n";
    f.commit();
  }
  std::ifstream in(target);
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "new");
  EXPECT_THROW(tread::host::ReplaceFile(dir / "no_such_dir" / "x.csv"), std::runtime_error);
}

// A target that is not a regular file (here /dev/null, as /dev/stdout would be) is written in
// place: no temporary beside it, and the device stays a device.
TEST(ReplaceFile, NonRegularTargetIsWrittenInPlace) {
  const std::filesystem::path null_device = "/dev/null";
  {
    tread::host::ReplaceFile f(null_device);
    EXPECT_EQ(f.temporary(), null_device);
    f.stream() << "discarded\n";
    f.commit();
  }
  EXPECT_EQ(std::filesystem::status(null_device).type(), std::filesystem::file_type::character);
}

}  // namespace
