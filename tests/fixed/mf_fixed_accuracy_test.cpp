// The Magic Formula in fixed point (mf::evaluate on fixed::Fixed64) against the double path, for
// every Magic Formula .tir in data/tyres and every useMode (111 … 222), over each file's input
// envelope (Fz in [0, FZMAX], κ in [KPUMIN, KPUMAX], α in [ALPMIN, ALPMAX], γ in [CAMMIN, CAMMAX],
// p in [PRESMIN, PRESMAX], Vx from standstill and reversing to 2·LONGVL, turn slip up to
// 0.5 1/m) and at its extremes (lifted wheel, FZMAX, the slip and camber limits, low speed): every
// output within 0.1 % of that output's peak (its largest |value| over the samples), and the
// status the same as in double (no overflow anywhere: an overflow would show as non_finite).
// Prints the worst ratio per file and useMode.
// Where |α| is within 0.01 rad of 90° the model itself is singular (tan α has its pole; α* and
// the side-slip speed follow it) and its value depends on the last bits of α in any arithmetic:
// there only the status and finiteness are compared, not the values.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "mf_fixed_input.hpp"
#include "mf_output_columns.hpp"
#include "shipped_mf_tyres.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

using fixed::Fixed64;

using testing::to_fixed;

/// The input exactly as the fixed path sees it (rounded to Q31.32), in double.
MfInput<double> rounded(const MfInput<double>& in) {
  const MfInput<Fixed64> f = to_fixed(in);
  MfInput<double> d;
  d.fz_n = f.fz_n.to_double();
  d.kappa = f.kappa.to_double();
  d.alpha_rad = f.alpha_rad.to_double();
  d.gamma_rad = f.gamma_rad.to_double();
  d.vx_mps = f.vx_mps.to_double();
  d.phit_1pm = f.phit_1pm.to_double();
  d.p_pa = f.p_pa.to_double();
  return d;
}

std::vector<MfInput<double>> envelope(const MfParameters<double>& p, bool turn_slip) {
  std::vector<MfInput<double>> inputs;
  std::mt19937_64 rng(20261125);
  const auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  const double fzmax = p.fzmax_n > 0.0 ? p.fzmax_n : 2.0 * p.fnomin_n;
  const double pmin = p.presmin_pa > 0.0 ? p.presmin_pa : 0.8 * p.nompres_pa;
  const double pmax = p.presmax_pa > pmin ? p.presmax_pa : 1.2 * p.nompres_pa;
  for (int i = 0; i < 1500; ++i) {
    MfInput<double> in;
    in.fz_n = uniform(0.0, fzmax);
    in.kappa = uniform(p.kpumin, p.kpumax);
    in.alpha_rad = uniform(p.alpmin_rad, p.alpmax_rad);
    in.gamma_rad = uniform(p.cammin_rad, p.cammax_rad);
    in.vx_mps =
        i % 10 == 0 ? uniform(-p.longvl_mps, 2.0 * p.vxlow_mps) : uniform(0.0, 2.0 * p.longvl_mps);
    in.p_pa = uniform(pmin, pmax);
    in.phit_1pm = turn_slip ? uniform(-0.5, 0.5) : 0.0;
    inputs.push_back(in);
  }
  // Light loads (1 N … FZMAX, evenly in log) with small cambers: where MF 6.2's camber deflection
  // alone may carry the wheel (its root above Romega), and where fixed point had rounded
  // γ²·(rtw/8)·|tan γ| to 0 below |γ| ≈ 0.002 rad (Rl 25 cm low).
  for (int i = 0; i < 300; ++i) {
    MfInput<double> in;
    in.fz_n = std::pow(10.0, uniform(0.0, std::log10(fzmax)));
    in.kappa = uniform(-0.05, 0.05);
    in.alpha_rad = uniform(-0.05, 0.05);
    in.gamma_rad = uniform(-0.005, 0.005);
    in.vx_mps = uniform(1.0, p.longvl_mps);
    in.p_pa = uniform(pmin, pmax);
    in.phit_1pm = turn_slip ? uniform(-0.1, 0.1) : 0.0;
    inputs.push_back(in);
  }
  // The extremes, in every combination of the limits that matter.
  for (const double fz : {0.0, 1.0, p.fnomin_n, fzmax}) {
    for (const double kappa : {p.kpumin, 0.0, p.kpumax}) {
      for (const double alpha : {p.alpmin_rad, 0.0, p.alpmax_rad}) {
        for (const double gamma : {p.cammin_rad, p.cammax_rad}) {
          for (const double vx : {0.0, 0.5 * p.vxlow_mps, p.longvl_mps, -p.longvl_mps}) {
            MfInput<double> in;
            in.fz_n = fz;
            in.kappa = kappa;
            in.alpha_rad = alpha;
            in.gamma_rad = gamma;
            in.vx_mps = vx;
            in.p_pa = pmax;
            in.phit_1pm = turn_slip ? 0.5 : 0.0;
            inputs.push_back(in);
          }
        }
      }
    }
  }
  return inputs;
}

constexpr double kConditionedAlpha_rad = 1.5707963267948966 - 0.01;

struct FileResult {
  std::string name;
  int mode = 0;
  double worst_ratio = 0.0;  // worst |fixed − double| / (0.1 % of the peak) over the outputs
  std::string worst_output;
};

TEST(MfFixedAccuracy, EveryMfTirEveryUseModeWithinOneThousandthOfEachPeak) {
  const auto columns = testing::output_columns<double>();
  const auto fixed_columns = testing::output_columns<Fixed64>();
  std::vector<FileResult> results;
  int files = 0;
  int status_differences = 0;
  for (const testing::ShippedMfTyre& shipped : testing::shipped_mf_tyre_files()) {
    const std::filesystem::path& file = shipped.file;
    const tyre::MfTirParameters& loaded = shipped.loaded;
    ++files;
    const MfParameters<double>& p = loaded.params;
    const MfParameters<Fixed64> pf = to_fixed_parameters(p);
    for (const int mode : {111, 112, 121, 122, 211, 212, 221, 222}) {
      const MfOptions options = options_from_use_mode(mode).value;
      const std::vector<MfInput<double>> inputs = envelope(p, options.use_turn_slip);
      std::vector<MfOutput<double>> want;
      std::vector<MfOutput<Fixed64>> got;
      for (const MfInput<double>& raw : inputs) {
        const MfInput<double> in = rounded(raw);
        want.push_back(evaluate(p, in, options));
        got.push_back(evaluate(pf, to_fixed(in), options));
        if (got.back().status != want.back().status && ++status_differences <= 5) {
          ADD_FAILURE() << file.filename() << " mode " << mode << ": status "
                        << static_cast<int>(got.back().status) << " (double "
                        << static_cast<int>(want.back().status) << ") at Fz " << in.fz_n
                        << " kappa " << in.kappa << " alpha " << in.alpha_rad << " gamma "
                        << in.gamma_rad << " Vx " << in.vx_mps << " phit " << in.phit_1pm;
          for (std::size_t c = 0; c < columns.size(); ++c) {
            std::printf("   %-12s fixed %.9g double %.9g\n", std::string(columns[c].name).c_str(),
                        (got.back().*fixed_columns[c].member).to_double(),
                        want.back().*columns[c].member);
          }
        }
      }
      FileResult r{file.filename().string(), mode, 0.0, ""};
      for (std::size_t c = 0; c < columns.size(); ++c) {
        double peak = 0.0;
        for (const auto& o : want) peak = std::max(peak, std::fabs(o.*columns[c].member));
        if (peak < 1e-12) continue;
        double worst = 0.0;
        std::size_t at = 0;
        for (std::size_t i = 0; i < want.size(); ++i) {
          if (!(std::fabs(inputs[i].alpha_rad) <= kConditionedAlpha_rad)) continue;
          const double e =
              std::fabs((got[i].*fixed_columns[c].member).to_double() - want[i].*columns[c].member);
          if (!std::isfinite(e)) {
            ADD_FAILURE() << r.name << " mode " << mode << " " << columns[c].name
                          << ": not a number, fixed "
                          << (got[i].*fixed_columns[c].member).to_double() << " double "
                          << want[i].*columns[c].member << " at sample " << i;
            continue;
          }
          if (e > worst) {
            worst = e;
            at = i;
          }
        }
        const double ratio = worst / (1e-3 * peak);
        EXPECT_LE(ratio, 1.0) << r.name << " mode " << mode << " " << columns[c].name
                              << ": |error| " << worst << " peak " << peak << " at Fz "
                              << inputs[at].fz_n << " kappa " << inputs[at].kappa << " alpha "
                              << inputs[at].alpha_rad << " gamma " << inputs[at].gamma_rad << " Vx "
                              << inputs[at].vx_mps << " phit " << inputs[at].phit_1pm << " p "
                              << inputs[at].p_pa << ": fixed "
                              << (got[at].*fixed_columns[c].member).to_double() << " double "
                              << want[at].*columns[c].member;
        if (ratio > r.worst_ratio) {
          r.worst_ratio = ratio;
          r.worst_output = std::string(columns[c].name);
        }
      }
      results.push_back(r);
    }
  }
  EXPECT_GE(files, 7);
  EXPECT_EQ(status_differences, 0);
  std::printf(
      "fixed point vs double: worst |error| as a fraction of 0.1 %% of the output's peak\n");
  for (const FileResult& r : results) {
    std::printf("  %-52s useMode %d  %.4f (%s)\n", r.name.c_str(), r.mode, r.worst_ratio,
                r.worst_output.c_str());
  }
}

}  // namespace
}  // namespace tread::mf
