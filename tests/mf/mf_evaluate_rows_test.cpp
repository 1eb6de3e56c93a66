// mf::evaluate_rows (src/mf/mf_evaluate_rows.hpp): many points in double, on double lanes where
// that gives evaluate<double>'s bits.
//   - Every point's outputs are evaluate<double>'s for it, bit for bit, with the same status:
//     every .tir the MF core loads, all eight useModes, extras on/off/loaded radius only, the three
//     mounted sides, physical and wild inputs (zero, huge, tiny, subnormal; NaN inputs), in double.
//     A difference names the first field that differs.
//   - A point's outputs do not depend on its neighbours, its place in its block or the span's
//     length.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "batch_inputs.hpp"
#include "golden_path.hpp"
#include "mf/mf_double_lanes.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_rows.hpp"
#include "mf/mf_lanes.hpp"
#include "shipped_mf_tyres.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "wild_value.hpp"

namespace tread::mf {
namespace {

/// n points in double: physical ones across the envelope with full double mantissas, every fifth
/// wild (zero, huge, tiny, subnormal in double's range), point 1's κ NaN and point 2's Fz inf.
std::vector<MfInput<double>> row_inputs(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> fz(-500.0, 12000.0), kappa(-1.0, 1.0), alpha(-0.6, 0.6),
      gamma(-0.2, 0.2), vx(-5.0, 60.0), phit(-2.0, 2.0), p(0.0, 4e5);
  std::vector<MfInput<double>> in(n);
  for (std::size_t i = 0; i < n; ++i) {
    MfInput<double>& x = in[i];
    if (i % 5 == 4) {
      x.fz_n = testing::wild<double>(rng, 5000.0);
      x.kappa = testing::wild<double>(rng, 0.2);
      x.alpha_rad = testing::wild<double>(rng, 0.2);
      x.gamma_rad = testing::wild<double>(rng, 0.05);
      x.vx_mps = testing::wild<double>(rng, 20.0);
      x.phit_1pm = testing::wild<double>(rng, 0.5);
      x.p_pa = testing::wild<double>(rng, 2e5);
    } else {
      x.fz_n = fz(rng);
      x.kappa = kappa(rng);
      x.alpha_rad = alpha(rng);
      x.gamma_rad = gamma(rng);
      x.vx_mps = i % 7 == 3 ? 0.0 : vx(rng);
      x.phit_1pm = i % 3 == 0 ? phit(rng) : 0.0;
      x.p_pa = p(rng);
    }
  }
  if (n > 1) in[1].kappa = std::numeric_limits<double>::quiet_NaN();
  if (n > 2) in[2].fz_n = std::numeric_limits<double>::infinity();
  return in;
}

constexpr std::size_t kFields = offsetof(MfOutput<double>, status) / sizeof(double);

/// The first field whose bits differ, or kFields.
std::size_t first_difference(const MfOutput<double>& a, const MfOutput<double>& b) {
  for (std::size_t k = 0; k < kFields; ++k) {
    if (std::memcmp(reinterpret_cast<const char*>(&a) + k * sizeof(double),
                    reinterpret_cast<const char*>(&b) + k * sizeof(double), sizeof(double)) != 0) {
      return k;
    }
  }
  return kFields;
}

double field(const MfOutput<double>& o, std::size_t k) {
  double v = 0.0;
  if (k < kFields)
    std::memcpy(&v, reinterpret_cast<const char*>(&o) + k * sizeof(double), sizeof v);
  return v;
}

std::string describe(const MfInput<double>& in) {
  char text[256];
  std::snprintf(text, sizeof text,
                " (Fz %.17g, kappa %.17g, alpha %.17g, gamma %.17g, Vx %.17g, phit %.17g, P %.17g)",
                in.fz_n, in.kappa, in.alpha_rad, in.gamma_rad, in.vx_mps, in.phit_1pm, in.p_pa);
  return text;
}

// Double lanes take double's choices (tolerances, approximants) in the MF 6.2 solve, float lanes
// float's.
static_assert(!detail::is_float_lanes<dlanes::DLanes<2>> && !detail::is_float_lanes<double>);
static_assert(detail::is_lanes<dlanes::DLanes<2>>);
static_assert(detail::is_float_lanes<lanes::F4> && detail::is_float_lanes<lanes::F8>);
static_assert(!detail::is_float_lanes<float>);

TEST(MfEvaluateRows, EqualsEvaluateDoubleBitForBit) {
  const std::vector<MfParameters<double>> tyres = testing::shipped_mf_tyres();
  ASSERT_GE(tyres.size(), 8U);
  std::mt19937_64 rng(23);
  const std::size_t n = 301;
  std::size_t compared = 0;
  for (const MfParameters<double>& p : tyres) {
    for (const testing::BatchOptionSet& set : testing::batch_option_sets()) {
      const std::vector<MfInput<double>> in = row_inputs(rng, n);
      std::vector<MfOutput<double>> got(n);
      evaluate_rows(p, in, set.options, got);
      for (std::size_t i = 0; i < n; ++i) {
        const MfOutput<double> want = evaluate(p, in[i], set.options);
        const std::string where = "fit " + std::to_string(static_cast<int>(p.fit_type)) + " " +
                                  set.name + " point " + std::to_string(i);
        ASSERT_EQ(got[i].status, want.status) << where;
        const std::size_t k = first_difference(got[i], want);
        ASSERT_EQ(k, kFields) << where << " field " << k << ": " << field(got[i], k) << " vs "
                              << field(want, k) << describe(in[i]);
        ++compared;
      }
    }
  }
  std::printf("[ compared ] %zu points on %d lane(s), all bit for bit\n", compared, rows_lanes());
}

TEST(MfEvaluateRows, EveryLengthAndPlaceInABlock) {
  for (const char* tyre : {"MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                           "chrono_Sedan_Pac02Tire.tir"}) {
    const MfParameters<double> p = tyre::load_mf_parameters(testing::tyre_file(tyre)).params;
    MfOptions o = options_from_use_mode(111).value;
    o.extras = true;
    std::mt19937_64 rng(5);
    const std::size_t most = 13;
    const std::vector<MfInput<double>> all = row_inputs(rng, most);
    for (std::size_t length = 0; length <= most; ++length) {
      for (std::size_t start = 0; start + length <= most; ++start) {
        std::vector<MfOutput<double>> got(length);
        evaluate_rows(p, std::span<const MfInput<double>>(all).subspan(start, length), o, got);
        for (std::size_t i = 0; i < length; ++i) {
          const MfOutput<double> want = evaluate(p, all[start + i], o);
          ASSERT_EQ(got[i].status, want.status) << tyre << " " << length << " " << start;
          ASSERT_EQ(first_difference(got[i], want), kFields)
              << tyre << " length " << length << " start " << start << " point " << i;
        }
      }
    }
  }
}

// MF 6.2's loaded-radius solve where a point's deflection can fall to zero between steps and
// rise again (the vertical stiffness reduced by camber, Q_CAM3·|γ| ≥ 1; a negative camber scale,
// ASPECT_RATIO > 2.15; a pressure factor 1 + PFZ1·dpi ≤ 0 with the limits off), beside every
// kind of neighbour: each point still gets evaluate<double>'s bits. The power's memo is updated
// only in the lanes whose power is used (fz62_pow_ratio's `used`): an unloaded lane, where the
// scalar does not call it, no longer has its memo set because its neighbour is loaded. (Counted
// once: this test makes about 8 900 such calls with an unloaded lane; before that change they did
// not change a bit here either, but a lane's later steps could depend on its neighbour.)
TEST(MfEvaluateRows, LoadedRadiusWhereTheDeflectionVanishesMidSolve) {
  const MfParameters<double> base =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula62_Parameters.tir")).params;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t compared = 0;
  for (int variant = 0; variant < 24; ++variant) {
    MfParameters<double> p = base;
    p.q_cam3 = std::array{base.q_cam3, 3.0, 30.0}[static_cast<std::size_t>(variant % 3)];
    p.aspect_ratio = variant % 2 == 0 ? base.aspect_ratio : 3.0;
    p.pfz1 = (variant / 2) % 2 == 0 ? base.pfz1 : 3.0;
    p.q_fcy2 = (variant / 4) % 2 == 0 ? base.q_fcy2 : 0.6;
    for (const int mode : {111, 211, 221}) {
      MfOptions o = options_from_use_mode(mode).value;
      o.extras = true;
      const std::size_t n = 400;
      std::vector<MfInput<double>> in(n);
      for (MfInput<double>& x : in) {
        x.fz_n = p.fnomin_n * 3.0 * unit(rng);
        x.kappa = 0.4 * (unit(rng) - 0.5);
        x.alpha_rad = 0.8 * (unit(rng) - 0.5);
        x.gamma_rad = 2.0 * (unit(rng) - 0.5);
        x.vx_mps = 1.0 + 40.0 * unit(rng);
        x.p_pa = p.nompres_pa * (0.1 + 1.9 * unit(rng));
      }
      std::vector<MfOutput<double>> got(n);
      evaluate_rows(p, in, o, got);
      for (std::size_t i = 0; i < n; ++i) {
        const MfOutput<double> want = evaluate(p, in[i], o);
        const std::string where =
            "variant " + std::to_string(variant) + " mode " + std::to_string(mode);
        ASSERT_EQ(got[i].status, want.status) << where;
        const std::size_t k = first_difference(got[i], want);
        ASSERT_EQ(k, kFields) << where << " point " << i << " field " << k << ": "
                              << field(got[i], k) << " vs " << field(want, k) << describe(in[i]);
        ++compared;
      }
    }
  }
  std::printf("[ compared ] %zu points, all bit for bit\n", compared);
}

}  // namespace
}  // namespace tread::mf
