// host::read_csv_number (sim/io/csv_number.hpp): fast_float reads the same cells as
// tir::parse_number (std::from_chars) to the same double, refuses the same ones, and reads a
// decimal comma where asked.
#include "io/csv_number.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <string>

#include "tir/tir_file.hpp"

namespace {

using tread::host::read_csv_number;

// read_csv_number as an optional, for comparisons.
std::optional<double> read(const std::string& cell, bool decimal_comma) {
  double v = 0.0;
  if (!read_csv_number(cell, decimal_comma, v)) return std::nullopt;
  return v;
}

void expect_same_as_parse_number(const std::string& cell) {
  const std::optional<double> fast = read(cell, false);
  const std::optional<double> reference = tread::tir::parse_number(cell);
  ASSERT_EQ(fast.has_value(), reference.has_value()) << "'" << cell << "'";
  if (fast) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*fast), std::bit_cast<std::uint64_t>(*reference))
        << "'" << cell << "'";
  }
}

TEST(CsvNumber, AcceptsAndRefusesWhatParseNumberDoes) {
  for (const char* cell : {"0",
                           "-0",
                           "+1",
                           "+-1",
                           "++1",
                           "-",
                           "+",
                           ".",
                           "1.",
                           ".5",
                           "-.5",
                           "+.5",
                           "1e5",
                           "1E+05",
                           "1e-5",
                           "1e",
                           "1e+",
                           "e5",
                           "1d3",
                           "1.5D-3",
                           "1.5d",
                           "0.1",
                           "3.14159265358979323846264338",
                           "00001",
                           "  7\t",
                           "\f8\r",
                           "1 2",
                           "1,5",
                           "1.5.3",
                           "nan",
                           "NaN",
                           "inf",
                           "-inf",
                           "infinity",
                           "1e400",
                           "-1e400",
                           "1e308",
                           "1.7976931348623157e308",
                           "1.8e308",
                           "1e-400",
                           "-1e-400",
                           "2e-324",
                           "3e-324",
                           "4.9e-324",
                           "1e-310",
                           "0e999999",
                           "0.000e-999",
                           "0x1p3",
                           "1_000",
                           "12345678901234567890",
                           "",
                           " ",
                           "1e5x",
                           "x1"}) {
    expect_same_as_parse_number(cell);
  }
  const std::string digits64 = "0." + std::string(62, '1');
  ASSERT_EQ(digits64.size(), 64U);
  expect_same_as_parse_number(digits64);
  expect_same_as_parse_number(digits64 + "1");  // 65 characters: refused by both
}

TEST(CsvNumber, RandomNumbersReadToTheSameDouble) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::uint64_t> any;
  char buffer[64];
  for (int i = 0; i < 20000; ++i) {
    const double v = std::bit_cast<double>(any(rng));
    if (!std::isfinite(v)) continue;
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    expect_same_as_parse_number(buffer);
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    expect_same_as_parse_number(buffer);
    std::snprintf(buffer, sizeof buffer, "%.3e", v);
    expect_same_as_parse_number(buffer);
    std::snprintf(buffer, sizeof buffer, "%.20f", v / 1e300);
    expect_same_as_parse_number(buffer);
  }
}

TEST(CsvNumber, DecimalComma) {
  EXPECT_EQ(read("0,05", true), 0.05);
  EXPECT_EQ(read("-1,5e3", true), -1500.0);
  EXPECT_EQ(read("1.5", true), 1.5);  // a point is still a point
  EXPECT_EQ(read(",5", true), 0.5);
  EXPECT_EQ(read("2,5D2", true), 250.0);
  EXPECT_FALSE(read("1,5.3", true));
  EXPECT_FALSE(read("1,5,3", true));
  EXPECT_FALSE(read("1,5", false));
}

}  // namespace
