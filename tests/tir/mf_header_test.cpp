// The MF constexpr header: generated at build time from MagicFormula61_Parameters.tir (float and
// double) and compared member by member, bit for bit, with the host loader's values
// (tyre::load_mf_parameters, converted with mf::convert_parameters<float> for the float header and
// mf::to_fixed_parameters for the Fixed64 one).
#include "tir/mf_header.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <type_traits>

#include "generated/mf61_params_double.hpp"
#include "generated/mf61_params_fixed.hpp"
#include "generated/mf61_params_float.hpp"
#include "golden_path.hpp"
#include "mf/mf_fixed.hpp"
#include "tir/tir_file.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

template <typename T>
auto bits(T v) {
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    return v.raw();
  } else if constexpr (sizeof(T) == 4) {
    return std::bit_cast<std::uint32_t>(v);
  } else {
    return std::bit_cast<std::uint64_t>(v);
  }
}

template <typename T>
void expect_identical(const tread::mf::MfParameters<T>& a, const tread::mf::MfParameters<T>& b) {
  EXPECT_EQ(a.fit_type, b.fit_type);
  EXPECT_EQ(a.tyre_side, b.tyre_side);
  int n = 0;
#define TREAD_MF_CHECK(member, section, key, dflt, description) \
  EXPECT_EQ(bits(a.member), bits(b.member)) << key;             \
  ++n;
  TREAD_MF_PARAMETER_LIST(TREAD_MF_CHECK)
#undef TREAD_MF_CHECK
  EXPECT_EQ(n, tread::mf::kMfParameterCount);
}

TEST(MfHeader, GeneratedParametersEqualTheLoader) {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const auto loaded = tread::tyre::load_mf_parameters(path).params;
  expect_identical(tyres::kMf61Double, loaded);
  expect_identical(tyres::kMf61Float, tread::mf::convert_parameters<float>(loaded));
  expect_identical(tyres::kMf61Fixed, tread::mf::to_fixed_parameters(loaded));
  EXPECT_EQ(tyres::kMf61Float.fit_type, tread::mf::FitType::mf61);
  EXPECT_EQ(tyres::kMf61Float.tyre_side, tread::mf::TyreSide::right);  // TYRESIDE = 'RIGHT'
}

// Compile-time use: the generated object is a constant expression.
static_assert(tyres::kMf61Float.fit_type == tread::mf::FitType::mf61);
static_assert(std::bit_cast<std::uint64_t>(tyres::kMf61Double.fnomin_n) ==
              std::bit_cast<std::uint64_t>(6752.0));  // FNOMIN in the file
static_assert(tyres::kMf61Fixed.fnomin_n == tread::fixed::Fixed64(6752.0));

TEST(MfHeader, RejectsBadNames) {
  tread::mf::MfParameters<double> p;
  EXPECT_THROW((void)tread::tir::generate_mf_header(p, {"1x", "ns", true, ""}),
               tread::tir::TirError);
  EXPECT_THROW((void)tread::tir::generate_mf_header(p, {"x", "a::", true, ""}),
               tread::tir::TirError);
}

}  // namespace
