// Golden traces: each rig scenario, run with the node in the loop (in-process bus, simulated
// clock), is compared with its trace stored under tests/golden (every 10th cycle). A numerical
// change in the tyre model, the node, the protocol or the rig's models shows up here, and the
// regenerated file shows it in review: TREAD_UPDATE_GOLDEN=1 rewrites the files instead of
// comparing.
//
// Tolerance, per column: |value - golden| <= 1e-6 * (largest |golden| of the column) + 1e-9. The
// run is deterministic on a machine and compiler (host and asan builds give the same traces); the
// tolerance only absorbs the last printed digits. It is deliberately tight: one force answer that
// rounds to a different 1 N step fails it, as any change of the numerics should show. Every 10th
// cycle is stored, to keep the files reviewable.
//
// The traces are recorded on x86-64 with AVX2 and FMA: there the node's four-lane tyre evaluation
// (src/mf/mf_evaluate_four.cpp) runs its x86-64-v3 clone or v4 code, which contract a·b + c into FMA
// instructions (in every build type: that file is always compiled -O2). A CPU without them runs
// the baseline clone, whose float results differ in the last bits; the closed loop carries that
// to whole 1 N answer steps (under qemu -cpu Nehalem: up to 21 % of the step steer's small Fx
// column). There a bit-level comparison means nothing, and the test is skipped with that reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "demo_run.hpp"

namespace tread::host {
namespace {

constexpr int kEvery = 10;

/// Whether this CPU runs the float path the traces were recorded with.
bool runs_recorded_float_path() {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

struct Table {
  std::string header;
  std::vector<std::vector<double>> rows;
};

Table read_table(const std::filesystem::path& p, int every) {
  Table t;
  std::ifstream in(p);
  if (!in) {
    ADD_FAILURE() << "cannot read " << p;
    return t;
  }
  std::getline(in, t.header);
  std::string line;
  int k = 0;
  while (std::getline(in, line)) {
    if (k++ % every != 0) continue;
    std::stringstream s(line);
    std::vector<double> row;
    for (std::string f; std::getline(s, f, ',');) row.push_back(std::stod(f));
    t.rows.push_back(row);
  }
  return t;
}

void write_table(const std::filesystem::path& p, const Table& t) {
  std::ofstream out(p);
  out << t.header << '\n' << std::setprecision(9);
  for (const auto& row : t.rows) {
    for (std::size_t k = 0; k < row.size(); ++k) out << (k == 0 ? "" : ",") << row[k];
    out << '\n';
  }
}

class GoldenTrace : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTrace, MatchesTheStoredTrace) {
  const std::string name = GetParam();
  if (!runs_recorded_float_path()) {
    GTEST_SKIP() << "recorded with the tyre lanes' FMA clone (x86-64-v3+); this CPU has no "
                    "AVX2/FMA and runs the baseline clone";
  }
  const DemoResult r = run_demo(testing::demo_settings({name}, "golden_" + name));
  ASSERT_EQ(r.scenarios.size(), 1U);
  const Table run = read_table(r.scenarios[0].trace_csv, kEvery);
  const std::filesystem::path golden =
      std::filesystem::path(TREAD_SOURCE_DIR) / "tests" / "golden" / (name + ".csv");
  if (const char* update = std::getenv("TREAD_UPDATE_GOLDEN");
      update != nullptr && *update == '1') {
    write_table(golden, run);
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden))
      << golden << " is missing (TREAD_UPDATE_GOLDEN=1 writes it)";
  const Table ref = read_table(golden, 1);
  ASSERT_EQ(run.header, ref.header) << "the trace's columns changed";
  ASSERT_EQ(run.rows.size(), ref.rows.size()) << "the run's length changed";
  std::stringstream cols(ref.header);
  std::vector<std::string> names;
  for (std::string f; std::getline(cols, f, ',');) names.push_back(f);
  std::vector<double> scale(names.size(), 0.0);
  for (const auto& row : ref.rows) {
    for (std::size_t k = 0; k < row.size() && k < scale.size(); ++k) {
      scale[k] = std::max(scale[k], std::abs(row[k]));
    }
  }
  int reported = 0;
  const double relative = 1e-6;
  double worst = 0.0;
  std::string worst_column;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    ASSERT_EQ(run.rows[i].size(), ref.rows[i].size());
    for (std::size_t k = 0; k < ref.rows[i].size(); ++k) {
      const double tol = relative * scale[k] + 1e-9;
      const double d = std::abs(run.rows[i][k] - ref.rows[i][k]);
      if (scale[k] > 0.0 && d / scale[k] > worst) {
        worst = d / scale[k];
        worst_column = names[k];
      }
      if (!(d <= tol) && reported++ < 10) {
        ADD_FAILURE() << name << ": t = " << ref.rows[i][0] << " s, " << names[k] << " = "
                      << run.rows[i][k] << ", golden " << ref.rows[i][k] << " (tolerance " << tol
                      << ")";
      }
    }
  }
  std::printf("[ worst    ] %s: %.3g of the column's largest value (%s)\n", name.c_str(), worst,
              worst_column.c_str());
}

INSTANTIATE_TEST_SUITE_P(Scenarios, GoldenTrace,
                         ::testing::Values("braking", "step-steer", "sine-dwell", "hunting",
                                           "sweep"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           std::string n = param.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

}  // namespace
}  // namespace tread::host
