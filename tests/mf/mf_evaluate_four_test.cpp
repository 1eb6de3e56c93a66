// mf::evaluate_four (src/mf/mf_evaluate_four.hpp): the Magic Formula on four float lanes.
//   - Golden: MFeval 4.3.1's tables, the same files, modes, edge cases and float tolerance as
//     mf_golden_test (2e-4 × the grid's largest |force| / |moment| / |column|), rows packed four
//     at a time, in order and with the rows shuffled over the lanes (then bit-identical per row:
//     a lane's result does not depend on its neighbours or its position).
//   - Against the scalar float evaluate over every .tir the MF core loads, all eight useModes,
//     combined on/off, extras off/on/loaded radius only, random physical inputs (low speed,
//     Vx = 0, negative Vx, Fz ≤ 0, turn slip, pressure): each column of each lane within a
//     tolerance relative to the column's scale, and the same status.
//   - Mounted sides mixed over the lanes; out-of-envelope status in one lane only; random finite
//     inputs (huge, tiny, subnormal) never give NaN/Inf; no allocation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "csv_table.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf_golden_compare.hpp"
#include "mf_output_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "wild_value.hpp"

#include "allocation_counter.hpp"  // this program's only source file: it defines the counters

namespace tread::mf {
namespace {

using Inputs4 = std::array<MfInput<float>, 4>;
using Outputs4 = std::array<MfOutput<float>, 4>;
using Sides4 = std::array<MountedSide, 4>;

constexpr std::array<int, 8> kUseModes = {111, 112, 121, 122, 211, 212, 221, 222};

/// Evaluates inputs[order[0]], inputs[order[1]], … four at a time (the last group padded with
/// its first input); returns the outputs by input index. Input i is mounted on sides[i].
std::vector<MfOutput<float>> evaluate_in_fours(const MfParameters<float>& p,
                                               const std::vector<MfInput<float>>& inputs,
                                               const std::vector<std::size_t>& order,
                                               const MfOptions& options,
                                               const std::vector<MountedSide>& sides) {
  std::vector<MfOutput<float>> out(inputs.size());
  for (std::size_t g = 0; g < order.size(); g += 4) {
    Inputs4 in;
    Sides4 side;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t i = order[g + k < order.size() ? g + k : g];
      in[k] = inputs[i];
      side[k] = sides[i];
    }
    Outputs4 o;
    evaluate_four(p, in, options, side, o);
    for (std::size_t k = 0; k < 4 && g + k < order.size(); ++k) out[order[g + k]] = o[k];
  }
  return out;
}

std::vector<std::size_t> identity(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

/// Every float column of two outputs equal bit for bit, and the same status.
bool bit_identical(const MfOutput<float>& a, const MfOutput<float>& b) {
  for (const auto& c : testing::output_columns<float>()) {
    if (std::bit_cast<std::uint32_t>(a.*(c.member)) != std::bit_cast<std::uint32_t>(b.*(c.member)))
      return false;
  }
  return a.status == b.status;
}

// ---- golden against MFeval --------------------------------------------------------------------

struct GoldenCase {
  const char* tir;
  const char* csv;
  std::size_t rows;
  std::vector<int> modes;
};

const std::vector<GoldenCase>& golden_cases() {
  static const std::vector<GoldenCase> cases = {
      {"MagicFormula61_Parameters.tir", "mfeval_MagicFormula61_Parameters_mode111.csv", 702, {111}},
      {"MagicFormula61_Parameters.tir", "mfeval_MagicFormula61_Parameters_mode121.csv", 702, {121}},
      {"MagicFormula52_Parameters.tir", "mfeval_MagicFormula52_Parameters_mode111.csv", 702, {111}},
      {"MagicFormula61_Parameters.tir",
       "mfeval_edge_MagicFormula61_Parameters.csv",
       92,
       {121, 122, 221, 222}},
  };
  return cases;
}

/// The golden comparison of one case through evaluate_four; with `shuffle_seed` ≠ 0 the rows are
/// shuffled over the lanes and each row's result must also equal the in-order one bit for bit.
void golden_four(const GoldenCase& gc, std::uint64_t shuffle_seed) {
  const testing::CsvTable table = testing::load_golden(gc.csv);
  ASSERT_EQ(table.rows.size(), gc.rows);
  const MfParameters<float> pf =
      convert_parameters<float>(tyre::load_mf_parameters(testing::tyre_file(gc.tir)).params);
  for (int mode : gc.modes) {
    const Result<MfOptions> options = options_from_use_mode(mode);
    ASSERT_TRUE(options.ok());
    const testing::GoldenRows g = testing::golden_rows(table, mode);
    std::vector<MfInput<float>> inputs;
    for (std::size_t r : g.rows) inputs.push_back(testing::golden_input<float>(table, r));
    const std::vector<MountedSide> sides(inputs.size(), MountedSide::as_measured);
    const std::vector<MfOutput<float>> in_order =
        evaluate_in_fours(pf, inputs, identity(inputs.size()), options.value, sides);
    std::vector<MfOutput<float>> outputs = in_order;
    if (shuffle_seed != 0) {
      std::vector<std::size_t> order = identity(inputs.size());
      std::mt19937_64 rng(shuffle_seed + static_cast<std::uint64_t>(mode));
      std::shuffle(order.begin(), order.end(), rng);
      outputs = evaluate_in_fours(pf, inputs, order, options.value, sides);
      int differing = 0;
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (!bit_identical(outputs[i], in_order[i]) && ++differing <= 5) {
          ADD_FAILURE() << gc.csv << " mode " << mode << " row " << g.rows[i]
                        << ": the result depends on the lane the row lands in";
        }
      }
      EXPECT_EQ(differing, 0);
    }
    const std::string what = std::string(gc.tir) + " mode " + std::to_string(mode) + " (four)";
    testing::GoldenFloatWorst worst;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      EXPECT_EQ(outputs[i].status, Status::ok) << what << " row " << g.rows[i];
      testing::check_golden_float_row(what, table, g, g.rows[i], outputs[i], worst);
    }
    EXPECT_GT(worst.compared, 0);
    std::printf("[ worst    ] %s%s: float %.3g (%s)\n", what.c_str(),
                shuffle_seed != 0 ? ", rows shuffled over the lanes" : "", worst.relative,
                worst.column.c_str());
  }
}

TEST(MfEvaluateFourGolden, Mf61Mode111Grid) {
  golden_four(golden_cases()[0], 0);
}
TEST(MfEvaluateFourGolden, Mf61Mode121Grid) {
  golden_four(golden_cases()[1], 0);
}
TEST(MfEvaluateFourGolden, Mf52Mode111Grid) {
  golden_four(golden_cases()[2], 0);
}
TEST(MfEvaluateFourGolden, Mf61EdgeCases) {
  golden_four(golden_cases()[3], 0);
}
TEST(MfEvaluateFourGolden, RowsShuffledOverTheLanesGiveTheSameResults) {
  for (const GoldenCase& gc : golden_cases()) golden_four(gc, 0x5eed);
}

// ---- against the scalar float evaluate ----------------------------------------------------------

/// Every .tir of the reference data the MF core loads (the others are named on stdout).
struct LoadedTir {
  std::string name;
  MfParameters<double> params;
};

std::vector<LoadedTir> loadable_tir_files() {
  const auto dir = testing::tyres_dir();
  EXPECT_TRUE(std::filesystem::is_directory(dir)) << dir << " is missing";
  std::vector<std::filesystem::path> paths;
  if (std::filesystem::is_directory(dir)) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() == ".tir") paths.push_back(e.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  std::vector<LoadedTir> files;
  for (const auto& path : paths) {
    try {
      files.push_back({path.filename().string(), tyre::load_mf_parameters(path).params});
    } catch (const std::exception& e) {
      std::printf("[ not MF   ] %s: %s\n", path.filename().string().c_str(), e.what());
    }
  }
  // The eight MF 5.2 / 6.1 / 6.2 / PAC2002 files of data/tyres at the time of writing.
  EXPECT_GE(files.size(), 8U);
  return files;
}

/// Random physical inputs: mostly the tyre's working range, with low speed (|Vx| < VXLOW),
/// Vx = 0, negative Vx, Fz = 0 and negative, limits crossed, turn slip and pressure.
MfInput<float> physical_input(std::mt19937_64& rng, const MfParameters<double>& p) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return static_cast<float>(lo + (hi - lo) * u(rng)); };
  MfInput<float> x;
  const double pick_fz = u(rng);
  x.fz_n = pick_fz < 0.05   ? 0.0f
           : pick_fz < 0.1  ? in(-0.5 * p.fnomin_n, 0.0)
           : pick_fz < 0.15 ? in(p.fzmax_n, 1.5 * p.fzmax_n)
                            : in(0.02 * p.fnomin_n, 2.5 * p.fnomin_n);
  const double pick_k = u(rng);
  x.kappa = pick_k < 0.05   ? 0.0f
            : pick_k < 0.7  ? in(-0.3, 0.3)
            : pick_k < 0.95 ? in(-1.0, 1.0)
                            : in(-3.0, 3.0);
  const double pick_a = u(rng);
  x.alpha_rad = pick_a < 0.05 ? 0.0f : pick_a < 0.75 ? in(-0.3, 0.3) : in(-1.2, 1.2);
  x.gamma_rad = u(rng) < 0.2 ? 0.0f : in(-0.2, 0.2);
  const double vxlow = p.vxlow_mps;
  const double pick_v = u(rng);
  x.vx_mps = pick_v < 0.05   ? 0.0f
             : pick_v < 0.2  ? in(-vxlow, vxlow)
             : pick_v < 0.35 ? in(-60.0, -vxlow)
             : pick_v < 0.4  ? in(vxlow, 2.0 * vxlow)
                             : in(vxlow, 60.0);
  x.phit_1pm = u(rng) < 0.4 ? 0.0f : in(-3.0, 3.0);
  x.p_pa = u(rng) < 0.4 ? 0.0f : in(0.6 * p.nompres_pa, 1.5 * p.nompres_pa);
  return x;
}

/// MF 6.1/6.2 take σx = |Kxk/Cx| and σy = |Kya/Cy| (MF 5.2 and PAC2002: PTX/PTY).
bool sigma_from_stiffness(const MfParameters<double>& p) {
  return p.fit_type == FitType::mf61 || p.fit_type == FitType::mf62;
}

struct OptionVariant {
  bool combined;
  bool extras;
  bool loaded_radius_only;
  const char* name;
};
constexpr std::array<OptionVariant, 6> kVariants = {{
    {true, true, false, "combined, extras"},
    {true, false, false, "combined"},
    {true, true, true, "combined, Rl only"},
    {false, true, false, "uncombined, extras"},
    {false, false, false, "uncombined"},
    {false, true, true, "uncombined, Rl only"},
}};

MfOptions make_options(int mode, const OptionVariant& v) {
  MfOptions o = options_from_use_mode(mode).value;
  o.combined = v.combined;
  o.extras = v.extras;
  o.extras_loaded_radius_only = v.loaded_radius_only;
  return o;
}

/// The worst |four − scalar| / scale of a set of rows, scale per column as the golden tests
/// take it (largest |force| for forces, |moment| for moments, |column| otherwise, over the
/// scalar results), never below 1e-6 (columns that are all 0, e.g. the extras when off).
///
/// Exceptions, the ratios: Cz = Fz/ρ, and in MF 6.1/6.2 σx = |Kxk/Cx|, σy = |Kya/Cy|. A ratio
/// inherits the relative differences of its terms, which can be far larger than float rounding
/// where a term is near 0: ρ at small loads (ρ = Romega − Rl, a difference of two radii, carries
/// ulp(R0) ≈ 3e-8 m), and C beyond FZMAX with the limits off, where the .tir's quadratic
/// Cx(dFz) = Cx0·(1 + PCFX1·dFz + PCFX2·dFz²) can cross zero (MagicFormula61: at Fz ≈
/// 1.49·FZMAX) and one rounding more or less (evaluate_four's x86-64-v3 and v4 code contract
/// a·b + c into FMAs, the scalar build does not) moves σ by far more than float rounding. A ratio
/// may differ by |ratio|·(sum of its terms' relative differences) on top of the tolerance; the
/// terms are held to the tolerance like every column. The worst error reported is the part beyond
/// that share; the points where the share was needed to pass are counted and printed.
struct ScalarCompare {
  double worst = 0.0;
  std::string where;
  int status_mismatches = 0;
  int nonfinite = 0;
  int inherited_points = 0;  // within a ratio's inherited share only
  double tolerance = 0.0;

  void merge(const ScalarCompare& other) {
    if (other.worst > worst) {
      worst = other.worst;
      where = other.where;
    }
    status_mismatches += other.status_mismatches;
    nonfinite += other.nonfinite;
    inherited_points += other.inherited_points;
  }

  void add(const std::string& what, const std::vector<MfOutput<float>>& scalar,
           const std::vector<MfOutput<float>>& four, const std::vector<MfInput<float>>& inputs,
           bool sigma_from_stiffness) {
    const auto columns = testing::output_columns<float>();
    double max_force = 0.0;
    double max_moment = 0.0;
    std::array<double, testing::output_columns<float>().size()> max_column{};
    for (const MfOutput<float>& s : scalar) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const double v = std::fabs(static_cast<double>(s.*(columns[c].member)));
        max_column[c] = std::max(max_column[c], v);
        if (columns[c].kind == testing::ColumnKind::force) max_force = std::max(max_force, v);
        if (columns[c].kind == testing::ColumnKind::moment) max_moment = std::max(max_moment, v);
      }
    }
    const auto relative_difference = [](float a, float b) {
      const double d = std::fabs(static_cast<double>(a) - static_cast<double>(b));
      return d > 0.0 ? d / std::fabs(static_cast<double>(b)) : 0.0;
    };
    for (std::size_t i = 0; i < scalar.size(); ++i) {
      if (scalar[i].status != four[i].status && ++status_mismatches <= 5) {
        ADD_FAILURE() << what << " input " << i << ": status differs";
      }
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const double s = static_cast<double>(scalar[i].*(columns[c].member));
        const double f = static_cast<double>(four[i].*(columns[c].member));
        if (!std::isfinite(f)) {
          if (++nonfinite <= 5) ADD_FAILURE() << what << " input " << i << " " << columns[c].name;
          continue;
        }
        double scale = max_column[c];
        if (columns[c].kind == testing::ColumnKind::force) scale = max_force;
        if (columns[c].kind == testing::ColumnKind::moment) scale = max_moment;
        scale = std::max(scale, 1e-6);
        double inherited = 0.0;  // a ratio's share of its terms' differences
        const MfOutput<float>& a = four[i];
        const MfOutput<float>& b = scalar[i];
        if (columns[c].name == "Cz_Npm") {
          inherited = std::fabs(s) * relative_difference(a.rho_m, b.rho_m);
        }
        if (sigma_from_stiffness && columns[c].name == "sigmax_m") {
          inherited = std::fabs(s) * (relative_difference(a.kxk_n, b.kxk_n) +
                                      relative_difference(a.cx_npm, b.cx_npm));
        }
        if (sigma_from_stiffness && columns[c].name == "sigmay_m") {
          inherited = std::fabs(s) * (relative_difference(a.kya_nprad, b.kya_nprad) +
                                      relative_difference(a.cy_npm, b.cy_npm));
        }
        const double d = std::fabs(f - s);
        const double rel = std::max(0.0, d - inherited) / scale;  // beyond the inherited share
        if (rel > tolerance) {
          const MfInput<float>& x = inputs[i];
          ADD_FAILURE() << what << " input " << i << " " << columns[c].name << ": four " << f
                        << " scalar " << s << " (" << rel << " of " << scale << ") for Fz "
                        << x.fz_n << " kappa " << x.kappa << " alpha " << x.alpha_rad << " gamma "
                        << x.gamma_rad << " Vx " << x.vx_mps << " phit " << x.phit_1pm << " P "
                        << x.p_pa;
        }
        if (d / scale > tolerance && rel <= tolerance) ++inherited_points;
        if (rel > worst) {
          worst = rel;
          where = what + " " + std::string(columns[c].name);
        }
      }
    }
  }
};

// Four lanes against the scalar float path, relative to the column's scale (see ScalarCompare).
// Measured on this x86-64 host (the x86-64-v4 code: FMAs) and with the default clone (SSE, no
// FMA): see the printed worst errors; a quarter of the float tolerance against MFeval (2e-4).
constexpr double kScalarTolerance = 5e-5;

TEST(MfEvaluateFour, EqualsTheScalarFloatEvaluateForEveryFileModeAndOption) {
  const std::vector<LoadedTir> files = loadable_tir_files();
  constexpr int kInputs = 400;  // per file, mode and option variant (100 calls)
  ScalarCompare all;
  all.tolerance = kScalarTolerance;
  const auto start = std::chrono::steady_clock::now();
  for (const LoadedTir& file : files) {
    const MfParameters<float> pf = convert_parameters<float>(file.params);
    ScalarCompare per_file;
    per_file.tolerance = kScalarTolerance;
    std::mt19937_64 rng(0xf0f0 + file.name.size());
    for (int mode : kUseModes) {
      for (const OptionVariant& v : kVariants) {
        const MfOptions o = make_options(mode, v);
        std::vector<MfInput<float>> inputs;
        std::vector<MfOutput<float>> scalar;
        for (int i = 0; i < kInputs; ++i) {
          inputs.push_back(physical_input(rng, file.params));
          scalar.push_back(evaluate(pf, inputs.back(), o));
        }
        const std::vector<MountedSide> sides(inputs.size(), MountedSide::as_measured);
        const std::vector<MfOutput<float>> four =
            evaluate_in_fours(pf, inputs, identity(inputs.size()), o, sides);
        per_file.add(file.name + " mode " + std::to_string(mode) + " " + v.name, scalar, four,
                     inputs, sigma_from_stiffness(file.params));
      }
    }
    std::printf(
        "[ max err  ] %s: four vs scalar float %.3g (%s); %d within a ratio's inherited share\n",
        file.name.c_str(), per_file.worst, per_file.where.c_str(), per_file.inherited_points);
    all.merge(per_file);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ max err  ] four vs scalar float, all files: %.3g of the column's scale (%s); "
      "%d within a ratio's inherited share; %zu files x 8 modes x 6 option sets x %d inputs in "
      "%.2f s\n",
      all.worst, all.where.c_str(), all.inherited_points, files.size(), kInputs, seconds);
  EXPECT_LE(all.worst, kScalarTolerance);
  EXPECT_EQ(all.status_mismatches, 0);
  EXPECT_EQ(all.nonfinite, 0);
}

TEST(MfEvaluateFour, MixedMountedSidesEqualTheScalarEvaluateWithThatSide) {
  // Every loadable file (TYRESIDE right: MagicFormula61/62; left: the others), every mode, the
  // sides of the four lanes drawn from {as_measured, left, right}; options.side of the call is
  // set to something else to show it is not used. Each lane equals the scalar evaluate with
  // options.side = its side, and — bit for bit — the unmirrored lane result mirrored.
  const std::vector<LoadedTir> files = loadable_tir_files();
  bool saw_left = false;
  bool saw_right = false;
  ScalarCompare all;
  all.tolerance = kScalarTolerance;
  int mirrored_lanes = 0;
  for (const LoadedTir& file : files) {
    saw_left = saw_left || file.params.tyre_side == TyreSide::left;
    saw_right = saw_right || file.params.tyre_side == TyreSide::right;
    const MfParameters<float> pf = convert_parameters<float>(file.params);
    std::mt19937_64 rng(0x51de + file.name.size());
    std::uniform_int_distribution<int> pick_side(0, 2);
    for (int mode : kUseModes) {
      for (bool combined : {true, false}) {
        MfOptions o = options_from_use_mode(mode).value;
        o.combined = combined;
        std::vector<MfInput<float>> inputs;
        std::vector<MountedSide> sides;
        std::vector<MfOutput<float>> scalar;
        for (int i = 0; i < 200; ++i) {
          inputs.push_back(physical_input(rng, file.params));
          sides.push_back(static_cast<MountedSide>(pick_side(rng)));
          MfOptions os = o;
          os.side = sides.back();
          scalar.push_back(evaluate(pf, inputs.back(), os));
        }
        MfOptions ignored = o;
        ignored.side = MountedSide::right;
        const std::vector<MfOutput<float>> four =
            evaluate_in_fours(pf, inputs, identity(inputs.size()), ignored, sides);
        all.add(file.name + " mode " + std::to_string(mode) + (combined ? "" : " uncombined"),
                scalar, four, inputs, sigma_from_stiffness(file.params));

        // The mirrored lanes: the as-measured result of the mirrored input, y → −y.
        std::vector<MfInput<float>> mirrored_inputs = inputs;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
          if (mirrored(sides[i], pf.tyre_side)) {
            mirrored_inputs[i].alpha_rad = -inputs[i].alpha_rad;
            mirrored_inputs[i].gamma_rad = -inputs[i].gamma_rad;
            mirrored_inputs[i].phit_1pm = -inputs[i].phit_1pm;
          }
        }
        const std::vector<MfOutput<float>> measured =
            evaluate_in_fours(pf, mirrored_inputs, identity(inputs.size()), o,
                              std::vector<MountedSide>(inputs.size(), MountedSide::as_measured));
        for (std::size_t i = 0; i < inputs.size(); ++i) {
          MfOutput<float> want = measured[i];
          if (mirrored(sides[i], pf.tyre_side)) {
            ++mirrored_lanes;
            want.fy_n = -want.fy_n;
            want.mx_nm = -want.mx_nm;
            want.mz_nm = -want.mz_nm;
            want.mzr_nm = -want.mzr_nm;
            want.alpha_rad = -want.alpha_rad;
            want.gamma_rad = -want.gamma_rad;
            want.phit_1pm = -want.phit_1pm;
          }
          EXPECT_TRUE(bit_identical(four[i], want)) << file.name << " mode " << mode << " " << i;
        }
      }
    }
  }
  EXPECT_TRUE(saw_left);
  EXPECT_TRUE(saw_right);
  EXPECT_GT(mirrored_lanes, 1000);
  std::printf(
      "[ max err  ] mixed sides, four vs scalar float: %.3g (%s); %d within a ratio's inherited "
      "share; %d "
      "mirrored lanes\n",
      all.worst, all.where.c_str(), all.inherited_points, mirrored_lanes);
  EXPECT_LE(all.worst, kScalarTolerance);
  EXPECT_EQ(all.status_mismatches, 0);
}

TEST(MfEvaluateFour, ResultsLeftInLanesEqualTheUnpackedResults) {
  // The overload that leaves MfOutput<lanes::F4>: lane i of every member is wheel i's value of the
  // std::array overload, bit for bit, and status lane i is set exactly where wheel i's status is
  // out_of_range (checks the transposition of the unpacking, member by member).
  const std::vector<LoadedTir> files = loadable_tir_files();
  int out_of_range_lanes = 0;
  for (const LoadedTir& file : files) {
    const MfParameters<float> pf = convert_parameters<float>(file.params);
    std::mt19937_64 rng(0x1a7e + file.name.size());
    std::uniform_int_distribution<int> pick_side(0, 2);
    for (int n = 0; n < 60; ++n) {
      Inputs4 in;
      Sides4 sides;
      for (std::size_t k = 0; k < 4; ++k) {
        in[k] = physical_input(rng, file.params);
        if ((n + static_cast<int>(k)) % 7 == 0) in[k].kappa = 1e6f;  // out of the envelope
        sides[k] = static_cast<MountedSide>(pick_side(rng));
      }
      const MfOptions o = make_options(kUseModes[static_cast<std::size_t>(n) % kUseModes.size()],
                                       kVariants[static_cast<std::size_t>(n) % kVariants.size()]);
      Outputs4 unpacked;
      evaluate_four(pf, in, o, sides, unpacked);
      MfOutput<lanes::F4> packed;
      evaluate_four(pf, in, o, sides, packed);
      const auto columns_f = testing::output_columns<float>();
      const auto columns_l = testing::output_columns<lanes::F4>();
      for (std::size_t k = 0; k < 4; ++k) {
        const int lane = static_cast<int>(k);
        for (std::size_t c = 0; c < columns_f.size(); ++c) {
          const float u = unpacked[k].*(columns_f[c].member);
          const float l = (packed.*(columns_l[c].member))[lane];
          EXPECT_EQ(std::bit_cast<std::uint32_t>(u), std::bit_cast<std::uint32_t>(l))
              << file.name << " " << columns_f[c].name << " lane " << lane;
        }
        EXPECT_EQ(packed.status[lane], unpacked[k].status);
        out_of_range_lanes += packed.status[lane] == Status::out_of_range ? 1 : 0;
      }
    }
  }
  EXPECT_GT(out_of_range_lanes, 0);
}

// ---- status per lane --------------------------------------------------------------------------

TEST(MfEvaluateFour, OutOfEnvelopeInOneLaneSetsOutOfRangeInThatLaneOnly) {
  // Each input beyond the finite-arithmetic envelope (mf_evaluate.hpp), in each lane: that lane's
  // status is out_of_range (as the scalar evaluate's) and its outputs are finite; the other three
  // lanes are ok and bit-identical to a call without the bad lane. The bad lane's values equal the
  // scalar float evaluate's as in the comparison above, the scale of a column taken over all bad
  // lanes of a mode (value by value they need not: at the envelope's Fz = 10·FZMAX, dFz ≈ 26, the
  // .tir's polynomials in dFz cancel, e.g. μx = PDX1 + PDX2·dFz, and a small Fx carries the
  // rounding of large terms).
  const tyre::MfTirParameters loaded =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir"));
  const MfParameters<float> pf = convert_parameters<float>(loaded.params);
  Inputs4 clean;
  clean[0] = {4000.0f, 0.05f, 0.03f, 0.01f, 20.0f, 0.0f, 0.0f};
  clean[1] = {7000.0f, -0.1f, -0.08f, -0.02f, 30.0f, 0.2f, 2.4e5f};
  clean[2] = {2500.0f, 0.0f, 0.15f, 0.0f, 0.5f, 0.0f, 0.0f};
  clean[3] = {9000.0f, 0.3f, 0.0f, 0.05f, -15.0f, -0.5f, 2.8e5f};
  struct Bad {
    const char* name;
    void (*apply)(MfInput<float>&);
  };
  const std::array<Bad, 9> bad = {{
      {"Fz = 1e12", [](MfInput<float>& x) { x.fz_n = 1e12f; }},
      {"kappa = 1e6", [](MfInput<float>& x) { x.kappa = 1e6f; }},
      {"kappa = -1e6", [](MfInput<float>& x) { x.kappa = -1e6f; }},
      {"alpha = 3", [](MfInput<float>& x) { x.alpha_rad = 3.0f; }},
      {"gamma = -2", [](MfInput<float>& x) { x.gamma_rad = -2.0f; }},
      {"Vx = 1e5", [](MfInput<float>& x) { x.vx_mps = 1e5f; }},
      {"phit = 1e4", [](MfInput<float>& x) { x.phit_1pm = 1e4f; }},
      {"P = 1e12", [](MfInput<float>& x) { x.p_pa = 1e12f; }},
      {"Fz = FLT_MAX", [](MfInput<float>& x) { x.fz_n = std::numeric_limits<float>::max(); }},
  }};
  const Sides4 sides = {MountedSide::left, MountedSide::right, MountedSide::as_measured,
                        MountedSide::left};
  ScalarCompare all;
  all.tolerance = kScalarTolerance;
  for (int mode : kUseModes) {
    const MfOptions o = options_from_use_mode(mode).value;
    Outputs4 base;
    evaluate_four(pf, clean, o, sides, base);
    for (std::size_t k = 0; k < 4; ++k) ASSERT_EQ(base[k].status, Status::ok) << k;
    std::vector<MfInput<float>> bad_inputs;
    std::vector<MfOutput<float>> scalar;
    std::vector<MfOutput<float>> four;
    for (const Bad& b : bad) {
      for (std::size_t lane = 0; lane < 4; ++lane) {
        Inputs4 in = clean;
        b.apply(in[lane]);
        Outputs4 out;
        evaluate_four(pf, in, o, sides, out);
        MfOptions os = o;
        os.side = sides[lane];
        bad_inputs.push_back(in[lane]);
        scalar.push_back(evaluate(pf, in[lane], os));
        four.push_back(out[lane]);
        EXPECT_EQ(scalar.back().status, Status::out_of_range) << b.name;
        EXPECT_EQ(out[lane].status, Status::out_of_range) << b.name << " mode " << mode;
        for (std::size_t k = 0; k < 4; ++k) {
          if (k == lane) continue;
          EXPECT_EQ(out[k].status, Status::ok) << b.name << " lane " << lane << " other " << k;
          EXPECT_TRUE(bit_identical(out[k], base[k])) << b.name << " lane " << lane;
        }
      }
    }
    all.add("out of envelope, mode " + std::to_string(mode), scalar, four, bad_inputs, true);
  }
  std::printf("[ max err  ] out-of-envelope lanes, four vs scalar float: %.3g (%s)\n", all.worst,
              all.where.c_str());
  EXPECT_EQ(all.status_mismatches, 0);
  EXPECT_EQ(all.nonfinite, 0);
}

// ---- fuzz: random finite inputs -----------------------------------------------------------------

TEST(MfEvaluateFour, RandomFiniteInputsNeverGiveNanOrInf) {
  const std::vector<LoadedTir> files = loadable_tir_files();
  const auto columns = testing::output_columns<float>();
  long evaluations = 0;
  int bad = 0;
  for (const LoadedTir& file : files) {
    const MfParameters<float> pf = convert_parameters<float>(file.params);
    std::mt19937_64 rng(0x7ead4 + file.name.size());
    std::uniform_int_distribution<int> pick_side(0, 2);
    for (int n = 0; n < 1500; ++n) {
      Inputs4 in;
      Sides4 sides;
      for (std::size_t k = 0; k < 4; ++k) {
        in[k].fz_n = testing::wild<float>(rng, 8000.0);
        in[k].kappa = testing::wild<float>(rng, 1.0);
        in[k].alpha_rad = testing::wild<float>(rng, 1.0);
        in[k].gamma_rad = testing::wild<float>(rng, 0.2);
        in[k].vx_mps = testing::wild<float>(rng, 30.0);
        in[k].phit_1pm = testing::wild<float>(rng, 0.5);
        in[k].p_pa = testing::wild<float>(rng, 3e5);
        sides[k] = static_cast<MountedSide>(pick_side(rng));
      }
      for (int mode : kUseModes) {
        const MfOptions o = make_options(mode, kVariants[static_cast<std::size_t>(n) % 6]);
        Outputs4 out;
        evaluate_four(pf, in, o, sides, out);
        ++evaluations;
        for (std::size_t k = 0; k < 4; ++k) {
          for (const auto& c : columns) {
            const float v = out[k].*(c.member);
            if (!std::isfinite(v) && ++bad <= 10) {
              const MfInput<float>& x = in[k];
              ADD_FAILURE() << file.name << " mode " << mode << " lane " << k << " " << c.name
                            << " = " << v << " for Fz " << x.fz_n << " kappa " << x.kappa
                            << " alpha " << x.alpha_rad << " gamma " << x.gamma_rad << " Vx "
                            << x.vx_mps << " phit " << x.phit_1pm << " P " << x.p_pa;
            }
          }
        }
      }
    }
  }
  std::printf("[ fuzz     ] %ld evaluate_four calls (%ld wheels), %d non-finite outputs\n",
              evaluations, 4 * evaluations, bad);
  EXPECT_EQ(bad, 0);
}

// ---- no allocation ------------------------------------------------------------------------------

TEST(MfEvaluateFour, TheAllocationCounterSeesNew) {  // the measurement itself is not vacuous
  testing::g_allocations = 0;
  testing::g_counting = true;
  auto* boxed = new std::array<int, 16>{};
  testing::g_counting = false;
  delete boxed;
  EXPECT_GE(testing::g_allocations.load(), 1U);
}

TEST(MfEvaluateFour, DoesNotAllocate) {
  // 100 000 calls on MF 6.1 (mode 111, extras), then every mode and option set on every file
  // (MF 5.2 / 6.2 / PAC2002: the loaded radius by bisection), inputs prepared beforehand.
  const std::vector<LoadedTir> files = loadable_tir_files();
  ASSERT_FALSE(files.empty());
  std::vector<MfParameters<float>> params;
  for (const LoadedTir& f : files) params.push_back(convert_parameters<float>(f.params));
  std::mt19937_64 rng(0xa110c);
  std::vector<Inputs4> inputs(1024);
  for (Inputs4& in : inputs) {
    for (MfInput<float>& x : in) x = physical_input(rng, files.front().params);
  }
  const Sides4 sides = {MountedSide::left, MountedSide::right, MountedSide::left,
                        MountedSide::right};
  const MfOptions o111 = options_from_use_mode(111).value;
  std::array<MfOptions, kUseModes.size() * kVariants.size()> all_options{};
  for (std::size_t m = 0; m < kUseModes.size(); ++m) {
    for (std::size_t v = 0; v < kVariants.size(); ++v) {
      all_options[m * kVariants.size() + v] = make_options(kUseModes[m], kVariants[v]);
    }
  }
  Outputs4 out;
  float sink = 0.0f;
  testing::g_allocations = 0;
  testing::g_counting = true;
  for (int i = 0; i < 100000; ++i) {
    evaluate_four(params.front(), inputs[static_cast<std::size_t>(i) % inputs.size()], o111, sides,
                  out);
    sink += out[static_cast<std::size_t>(i) % 4].fx_n;
  }
  for (const MfParameters<float>& p : params) {
    for (std::size_t j = 0; j < all_options.size(); ++j) {
      for (std::size_t i = 0; i < 20; ++i) {
        evaluate_four(p, inputs[(j * 20 + i) % inputs.size()], all_options[j], sides, out);
        sink += out[i % 4].fy_n;
      }
    }
  }
  testing::g_counting = false;
  EXPECT_EQ(testing::g_allocations.load(), 0U);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace tread::mf
