// Defective parameter sets (fuzz): every key of TREAD_MF_PARAMETER_LIST in turn set to 0, its
// negative, huge and tiny, with random wild inputs (and NaN/inf inputs), in double, float and four
// float lanes: no output is ever NaN or inf, and a non-finite result is reported as
// Status::non_finite (never as ok). Parameter sets no tyre has (zero vertical stiffness, nominal
// load or radius) give non_finite at an ordinary operating point.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf_output_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "wild_value.hpp"

namespace tread::mf {
namespace {

using testing::wild;

struct Key {
  const char* name;
  double MfParameters<double>::*member;
};

std::vector<Key> all_keys() {
  std::vector<Key> keys;
#define TREAD_MF_KEY(member, section, key, value, description) \
  keys.push_back({key, &MfParameters<double>::member});
  TREAD_MF_PARAMETER_LIST(TREAD_MF_KEY)
#undef TREAD_MF_KEY
  return keys;
}

MfParameters<double> load(const std::string& name) {
  return tyre::load_mf_parameters(testing::tyre_file(name)).params;
}

template <typename T>
MfInput<T> nominal_input() {
  MfInput<T> in;
  in.fz_n = T(5000);
  in.kappa = T(0.05);
  in.alpha_rad = T(0.05);
  in.gamma_rad = T(0.02);
  in.vx_mps = T(16.7);
  return in;
}

/// Counts the outputs that are NaN or inf (must stay 0) and the evaluations per status.
struct Tally {
  int non_finite_values = 0;
  int non_finite_status = 0;
  int evaluations = 0;
  std::string first;
};

template <typename T>
void check(const MfOutput<T>& out, Status status, const std::string& what, Tally& tally) {
  ++tally.evaluations;
  if (status == Status::non_finite) ++tally.non_finite_status;
  for (const auto& c : testing::output_columns<T>()) {
    const T v = out.*(c.member);
    if (!std::isfinite(v)) {
      if (tally.non_finite_values++ == 0) {
        tally.first =
            what + ": " + std::string(c.name) + " = " + std::to_string(static_cast<double>(v));
      }
    }
  }
}

/// Evaluates `p` (double, float, four lanes) for random wild inputs in several modes.
void fuzz_set(const MfParameters<double>& p, const std::string& what, std::mt19937_64& rng,
              Tally& tally) {
  const MfParameters<float> pf = convert_parameters<float>(p);
  constexpr std::array<int, 4> kModes = {111, 121, 212, 222};
  std::array<MfInput<float>, 4> four_in{};
  for (int i = 0; i < 8; ++i) {
    MfInput<double> in = i == 0 ? nominal_input<double>() : MfInput<double>{};
    if (i > 0) {
      in.fz_n = wild<float>(rng, 8000.0);
      in.kappa = wild<float>(rng, 1.0);
      in.alpha_rad = wild<float>(rng, 1.0);
      in.gamma_rad = wild<float>(rng, 0.2);
      in.vx_mps = wild<float>(rng, 30.0);
      in.phit_1pm = wild<float>(rng, 0.5);
      in.p_pa = wild<float>(rng, 3e5);
    }
    MfOptions o = options_from_use_mode(kModes[static_cast<std::size_t>(i) % kModes.size()]).value;
    o.combined = i % 3 != 0;
    const MfOutput<double> d = evaluate(p, in, o);
    check(d, d.status, what + " double", tally);
    MfInput<float> fin;
    fin.fz_n = static_cast<float>(in.fz_n);
    fin.kappa = static_cast<float>(in.kappa);
    fin.alpha_rad = static_cast<float>(in.alpha_rad);
    fin.gamma_rad = static_cast<float>(in.gamma_rad);
    fin.vx_mps = static_cast<float>(in.vx_mps);
    fin.phit_1pm = static_cast<float>(in.phit_1pm);
    fin.p_pa = static_cast<float>(in.p_pa);
    const MfOutput<float> f = evaluate(pf, fin, o);
    check(f, f.status, what + " float", tally);
    four_in[static_cast<std::size_t>(i) % 4] = fin;
    if (i % 4 == 3) {
      std::array<MfOutput<float>, 4> four{};
      const std::array<MountedSide, 4> sides{MountedSide::left, MountedSide::right,
                                             MountedSide::as_measured, MountedSide::left};
      evaluate_four(pf, four_in, o, sides, four);
      for (const auto& out : four) check(out, out.status, what + " four lanes", tally);
    }
  }
}

class MfDefectiveParameters : public ::testing::TestWithParam<std::string> {};

TEST_P(MfDefectiveParameters, NoKeyValueGivesNanOrInfUnderStatusOk) {
  const MfParameters<double> base = load(GetParam());
  std::mt19937_64 rng(0xdefec7);
  Tally tally;
  for (const Key& key : all_keys()) {
    const double v = base.*(key.member);
    const double huge = 1e300;
    for (const double value : {0.0, -v, -1.0, huge, -huge, 1e-300, 3e38, 1e-38}) {
      MfParameters<double> p = base;
      p.*(key.member) = value;
      fuzz_set(p, GetParam() + " " + key.name + " = " + std::to_string(value), rng, tally);
    }
  }
  EXPECT_EQ(tally.non_finite_values, 0) << tally.first;
  // The defective sets do make results non-finite somewhere: the status said so.
  EXPECT_GT(tally.non_finite_status, 0);
  EXPECT_GT(tally.evaluations, 20000);
}

INSTANTIATE_TEST_SUITE_P(Files, MfDefectiveParameters,
                         ::testing::Values("MagicFormula61_Parameters.tir",
                                           "MagicFormula62_Parameters.tir",
                                           "MagicFormula52_Parameters.tir"));

/// The defects of issue 12: an ordinary operating point gives non_finite (not ok), every output
/// finite, in double, float and four lanes.
TEST(MfDefectiveParameters, ZeroStiffnessLoadOrRadiusIsNonFiniteNotOk) {
  for (const char* file : {"MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                           "MagicFormula52_Parameters.tir"}) {
    const MfParameters<double> base = load(file);
    for (double MfParameters<double>::*member :
         {&MfParameters<double>::vertical_stiffness_npm, &MfParameters<double>::fnomin_n,
          &MfParameters<double>::unloaded_radius_m}) {
      MfParameters<double> p = base;
      p.*member = 0.0;
      const MfOptions o = options_from_use_mode(111).value;
      Tally tally;
      const MfOutput<double> d = evaluate(p, nominal_input<double>(), o);
      EXPECT_EQ(d.status, Status::non_finite) << file;
      check(d, d.status, file, tally);
      const MfParameters<float> pf = convert_parameters<float>(p);
      const MfOutput<float> f = evaluate(pf, nominal_input<float>(), o);
      EXPECT_EQ(f.status, Status::non_finite) << file;
      check(f, f.status, file, tally);
      std::array<MfInput<float>, 4> in{};
      in.fill(nominal_input<float>());
      in[2].fz_n = 3000.0F;
      std::array<MfOutput<float>, 4> four{};
      evaluate_four(pf, in, o, {}, four);
      for (const auto& out : four) {
        EXPECT_EQ(out.status, Status::non_finite) << file;
        check(out, out.status, file, tally);
      }
      EXPECT_EQ(tally.non_finite_values, 0) << tally.first;
    }
  }
}

TEST(MfDefectiveParameters, SoundFileAtAnOrdinaryPointIsOkAndUnchanged) {
  const MfParameters<double> p = load("MagicFormula61_Parameters.tir");
  const MfOutput<double> d = evaluate(p, nominal_input<double>(), options_from_use_mode(111).value);
  EXPECT_EQ(d.status, Status::ok);
  EXPECT_GT(d.rl_m, 0.3);
  EXPECT_LT(d.rl_m, p.unloaded_radius_m);
}

/// A NaN or infinite input (a caller that does not validate) gives non_finite, not NaN.
TEST(MfDefectiveParameters, NanOrInfInputIsNonFinite) {
  const MfParameters<double> p = load("MagicFormula62_Parameters.tir");
  const MfParameters<float> pf = convert_parameters<float>(p);
  const MfOptions o = options_from_use_mode(111).value;
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int field = 0; field < 7; ++field) {
    for (const double bad : {kNan, kInf, -kInf}) {
      MfInput<double> in = nominal_input<double>();
      double* fields[] = {&in.fz_n,   &in.kappa,    &in.alpha_rad, &in.gamma_rad,
                          &in.vx_mps, &in.phit_1pm, &in.p_pa};
      *fields[field] = bad;
      Tally tally;
      const MfOutput<double> d = evaluate(p, in, o);
      check(d, d.status, "double", tally);
      MfInput<float> fin = nominal_input<float>();
      float* ffields[] = {&fin.fz_n,   &fin.kappa,    &fin.alpha_rad, &fin.gamma_rad,
                          &fin.vx_mps, &fin.phit_1pm, &fin.p_pa};
      *ffields[field] = static_cast<float>(bad);
      const MfOutput<float> f = evaluate(pf, fin, o);
      check(f, f.status, "float", tally);
      std::array<MfInput<float>, 4> in4{};
      in4.fill(nominal_input<float>());
      in4[1] = fin;
      std::array<MfOutput<float>, 4> four{};
      evaluate_four(pf, in4, o, {}, four);
      for (const auto& out : four) check(out, out.status, "four", tally);
      EXPECT_EQ(tally.non_finite_values, 0) << "field " << field << " " << tally.first;
      // An infinite input the envelope clamps (e.g. Fz = +inf → 10·FZMAX) may stay ok; a NaN
      // never does, but for the pressure, where NaN (like 0) means the file's INFLPRES.
      if (field == 6 && std::isnan(bad)) {
        EXPECT_EQ(d.status, Status::ok);
        EXPECT_DOUBLE_EQ(d.p_pa, p.inflpres_pa);
      } else if (std::isnan(bad)) {
        EXPECT_NE(d.status, Status::ok) << "field " << field;
        EXPECT_NE(f.status, Status::ok) << "field " << field;
        EXPECT_NE(four[1].status, Status::ok) << "field " << field;
      }
      EXPECT_EQ(four[0].status, Status::ok) << "field " << field;  // the other lanes untouched
      EXPECT_EQ(four[2].status, Status::ok) << "field " << field;
    }
  }
}

}  // namespace
}  // namespace tread::mf
