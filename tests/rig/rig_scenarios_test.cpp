// The rig's physics checks with the node in the loop (in-process bus, simulated clock): every force
// and delta r the vehicle and the wheelsets are driven by is the node's float answer after the
// protocol's quantisation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "contact/contact_setup.hpp"
#include "contact/equivalent_conicity.hpp"
#include "contact/klingel.hpp"
#include "demo_run.hpp"
#include "mf/mf_evaluate.hpp"
#include "rig/hunting_scenario.hpp"
#include "runtime/node_runtime.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/vehicle_params.hpp"

namespace tread::host {
namespace {

using testing::demo_settings;
using testing::find_outcome;
using testing::metric;

/// Columns of a scenario's trace CSV by name.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] std::size_t col(const std::string& n) const {
    const auto it = std::find(names.begin(), names.end(), n);
    return static_cast<std::size_t>(it - names.begin());
  }
};

Csv read_csv(const std::filesystem::path& p) {
  Csv c;
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  for (std::string f; std::getline(h, f, ',');) c.names.push_back(f);
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<double> row;
    for (std::string f; std::getline(s, f, ',');) row.push_back(std::stod(f));
    c.rows.push_back(row);
  }
  return c;
}

TEST(RigScenarios, HuntingWavelengthMatchesKlingelAtTheEquivalentConicity) {
  // Three wheel/rail pairs, two amplitudes each (the two wheelsets): the wavelength of the motion
  // driven by the node's delta r over CAN against Klingel's formula with the EN 15302 equivalent
  // conicity (Annex B, computed by the rig from its own table in double) at the measured
  // amplitude, and the wheelset's own e0 = b2b/2 + 70 mm and r0 (metre gauge: 532.5 mm, 440 mm).
  for (const std::string profile :
       {"wheel=S1002,rail=60E1,cant=1:40", "wheel=S1002,rail=60E1,cant=1:20",
        "wheel=S1002,rail=60E1,cant=1:40,gauge=1000,b2b=925,r0=440"}) {
    const DemoResult r = run_demo(demo_settings({"hunting"}, "hunting", profile));
    const ScenarioOutcome* o = find_outcome(r, "hunting");
    ASSERT_NE(o, nullptr);
    EXPECT_EQ(o->check.stale_answers, 0U);
    EXPECT_LE(o->check.max_delta_r_error_mm, 0.0006);
    for (int j = 0; j < 2; ++j) {
      const std::string w = "wheelset " + std::to_string(j) + " ";
      const double wavelength_m = metric(*o, w + "hunting wavelength");
      const double amplitude_mm = metric(*o, w + "amplitude");
      ASSERT_TRUE(std::isfinite(wavelength_m)) << profile;
      // Independently of the scenario's own figure: the conicity from a fresh table.
      const contact::ContactSetup setup = parse_wheelset_profile(profile);
      const contact::ContactTable table = contact::build_contact(setup).table(-12.0, 12.0, 0.1);
      const double tan_gamma_e = contact::equivalent_conicity(table, amplitude_mm).tan_gamma_e;
      const double e0_mm = 0.5 * setup.back_to_back_mm + 70.0;
      const double klingel_m =
          contact::klingel_wavelength_mm(tan_gamma_e, setup.r0_mm, e0_mm) / 1000.0;
      EXPECT_NEAR(wavelength_m / klingel_m, 1.0, 0.02)
          << profile << " wheelset " << j << ": " << wavelength_m << " m vs Klingel " << klingel_m
          << " m at tan(gamma_e) " << tan_gamma_e << ", amplitude " << amplitude_mm;
      EXPECT_GT(amplitude_mm, 2.0);
    }
  }
}

TEST(RigScenarios, HuntingWithTooFewPeriodsSaysSoInsteadOfPrintingNaNAsAResult) {
  // The scenario before its first step: no period seen. Every metric is NaN with the reason, and
  // none claims a Klingel comparison.
  HuntingSettings s;
  s.wheelsets = 1;
  s.wheelset_profile = "wheel=S1002,rail=60E1,cant=1:40";
  const HuntingScenario scenario(s);
  const std::vector<ScenarioMetric> m = scenario.metrics();
  ASSERT_EQ(m.size(), 4U);
  for (const ScenarioMetric& x : m) {
    EXPECT_TRUE(std::isnan(x.value)) << x.name;
    EXPECT_EQ(x.note, "not measured: 0 full periods in the run, two needed") << x.name;
  }
}

TEST(RigScenarios, BrakingDecelerationIsBoundedByThePeakFrictionOfTheNodesTyre) {
  const DemoResult r = run_demo(demo_settings({"braking"}, "braking"));
  const ScenarioOutcome* o = find_outcome(r, "braking");
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->check.stale_answers, 0U);
  const double decel = metric(*o, "mean_deceleration");
  // The peak of |Fx|/Fz of the tyre (double) over slip at the wheel loads of the run: the car
  // cannot decelerate by more than mu_peak g with every wheel at its own peak.
  const Csv c = read_csv(o->trace_csv);
  const mf::MfParameters<double> tyre =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params;
  double fz_front = 0.0;
  double fz_rear = 0.0;
  const std::size_t mid = c.rows.size() / 2;  // steady braking
  fz_front = c.rows[mid][c.col("Fz_N_0")];
  fz_rear = c.rows[mid][c.col("Fz_N_2")];
  const auto peak = [&](double fz) {
    double best = 0.0;
    for (int k = 0; k <= 1000; ++k) {
      mf::MfInput<double> in;
      in.fz_n = fz;
      in.vx_mps = 15.0;
      in.kappa = -0.001 * k;
      best = std::max(best, std::abs(mf::evaluate(tyre, in, {}).fx_n));
    }
    return best;
  };
  const double g = 9.81;
  const double max_decel = 2.0 * (peak(fz_front) + peak(fz_rear)) / 1500.0;
  EXPECT_LE(decel, max_decel * 1.001);
  EXPECT_GE(decel, 0.97 * max_decel) << "ABS should hold every wheel near its peak";
  EXPECT_GT(decel, 0.9 * g);  // this tyre's peak friction is above 1
  // The same manoeuvre with the tyre in double, in process: the CAN loop changes little.
  for (const ScenarioMetric& m : o->metrics) {
    if (m.name == "mean_deceleration") {
      const double ref = std::stod(m.note.substr(m.note.find(':') + 1));
      EXPECT_NEAR(decel / ref, 1.0, 0.002);
    }
  }
}

TEST(RigScenarios, SteadyCorneringSatisfiesTheLateralForceBalance) {
  const DemoResult r = run_demo(demo_settings({"step-steer"}, "step_steer"));
  const ScenarioOutcome* o = find_outcome(r, "step-steer");
  ASSERT_NE(o, nullptr);
  const Csv c = read_csv(o->trace_csv);
  const vehicle::VehicleParams p;
  // Average over the last 0.5 s (steady state): m ay = sum of the tyre forces across the body
  // (front forces turned by the road-wheel angle), ay = vx r, and no net yaw moment.
  double ay = 0.0, fy_body = 0.0, vx_r = 0.0, mz_body = 0.0;
  std::size_t n = 0;
  for (std::size_t i = c.rows.size() - 500; i < c.rows.size(); ++i) {
    const auto& row = c.rows[i];
    const double delta =
        row[c.col("steer_wheel_deg")] * std::numbers::pi / 180.0 / p.steering_ratio;
    double fy = 0.0, mz = 0.0;
    for (int w = 0; w < 4; ++w) {
      const std::string k = std::to_string(w);
      const double fxw = row[c.col("Fx_N_" + k)];
      const double fyw = row[c.col("Fy_N_" + k)];
      const double a = w < 2 ? delta : 0.0;
      const double fx_b = fxw * std::cos(a) - fyw * std::sin(a);
      const double fy_b = fxw * std::sin(a) + fyw * std::cos(a);
      fy += fy_b;
      mz += p.wheel_x_m(static_cast<std::size_t>(w)) * fy_b -
            p.wheel_y_m(static_cast<std::size_t>(w)) * fx_b + row[c.col("Mz_Nm_" + k)];
    }
    ay += row[c.col("ay_mps2")];
    fy_body += fy;
    mz_body += mz;
    vx_r += row[c.col("vx_mps")] * row[c.col("yaw_rate_radps")];
    ++n;
  }
  ay /= static_cast<double>(n);
  fy_body /= static_cast<double>(n);
  vx_r /= static_cast<double>(n);
  mz_body /= static_cast<double>(n);
  EXPECT_NEAR(ay, 4.0, 0.1);
  // Steady state: the centripetal acceleration vx r (kinematics) is carried by the tyre forces the
  // node answered over CAN (m vx r = sum Fy across the body), and equals the body's ay.
  EXPECT_NEAR(p.mass_kg * vx_r / fy_body, 1.0, 0.01);
  EXPECT_NEAR(vx_r / ay, 1.0, 0.01);
  EXPECT_LT(std::abs(mz_body), 0.01 * fy_body * p.wheelbase_m());
}

/// The protocol ran clean and every answer of the node was within `max_force_error_n` (and 0.03 N
/// m) of the reference model in double; Δr within `max_delta_r_error_mm` where wheelsets ran.
void expect_answers_match(const DemoResult& r, double max_force_error_n,
                          double max_delta_r_error_mm) {
  EXPECT_EQ(r.rig_frames_rejected, 0U);
  EXPECT_EQ(r.unanswered_cycles, 0U);
  EXPECT_EQ(r.report.counters.rx_bad_crc + r.report.counters.rx_bad_counter +
                r.report.counters.rx_bad_length,
            0U);
  for (const ScenarioOutcome& o : r.scenarios) {
    EXPECT_GT(o.check.answers_checked, 1000U) << o.name;
    EXPECT_LE(o.check.max_force_error_n, max_force_error_n) << o.name;
    EXPECT_LE(o.check.max_moment_error_nm, 0.03) << o.name;
    EXPECT_LE(o.check.max_delta_r_error_mm, max_delta_r_error_mm) << o.name;
  }
}

TEST(RigScenarios, EveryAnswerMatchesTheReferenceModel) {
  const DemoResult r = run_demo(demo_settings({"sine-dwell", "sweep"}, "answers"));
  ASSERT_EQ(r.scenarios.size(), 2U);
  // Quantisation of the force signals (0.5 N steps: 0.25 N rounding) plus float on 7 kN; Δr: the
  // signal's 1 µm step (0.5 µm rounding) plus float on the float table.
  expect_answers_match(r, 0.6, 0.00051);
}

// The fixed-point node (`tread demo --fixed`: the FPU-less image's arithmetic) answers within the
// same bounds: its Magic Formula is within 0.1 % of the peak of double (tests/fixed), far below the
// force signals' 0.5 N step on 7 kN, and its contact table is the flashed integer one (0.1 µm).
TEST(RigScenarios, EveryAnswerOfTheFixedPointNodeMatchesTheReferenceModel) {
  DemoSettings settings = demo_settings({"sine-dwell", "sweep", "hunting"}, "answers_fixed");
  settings.node.fixed = true;
  const DemoResult r = run_demo(settings);
  ASSERT_EQ(r.scenarios.size(), 3U);
  EXPECT_EQ(r.report.loop.overruns, 0U);
  // Δr: the signal's 1 µm step (0.5 µm rounding) plus the integer table's rows rounded to 0.1 µm
  // (0.05 µm) and the interpolated value rounded to 0.1 µm again (0.05 µm).
  expect_answers_match(r, 0.6, 0.0006);
  const ScenarioOutcome* hunting = find_outcome(r, "hunting");
  ASSERT_NE(hunting, nullptr);
  EXPECT_LT(std::abs(metric(*hunting, "wheelset 0 wavelength vs Klingel")), 1.0);
}

}  // namespace
}  // namespace tread::host
