// The rig as over CAN: the node's float Magic Formula, the protocol's quantisation, and the
// answer one cycle late — the per-step API (wheel_inputs → forces → step) driven by hand, with
// and without the delay compensation.
#include "vehicle/delay_compensation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/manoeuvre.hpp"
#include "vehicle/manoeuvre_runner.hpp"

namespace tread::vehicle {
namespace {

constexpr double kDt = 1e-3;

double quantise(double x, double step) {
  return std::round(x / step) * step;
}

/// The node as the rig sees it: inputs quantised as the classic layout's signals (κ 5e-5, α
/// 2e-5 rad, γ 1e-5 rad, Fz 1 N, Vx 0.01 m/s), the Magic Formula in float, the forces quantised
/// (1 N, Mz 0.05 N m).
class NodeEmulation {
 public:
  explicit NodeEmulation(const mf::MfParameters<double>& params)
      : params_(mf::convert_parameters<float>(params)) {
    options_.extras = false;
  }
  std::array<WheelForces, kWheelCount> answer(
      const std::array<WheelKinematics, kWheelCount>& inputs) const {
    std::array<WheelForces, kWheelCount> out{};
    for (std::size_t i = 0; i < kWheelCount; ++i) {
      const WheelKinematics& k = inputs[i];
      mf::MfInput<float> in;
      in.kappa = static_cast<float>(quantise(k.kappa, 5e-5));
      in.alpha_rad = static_cast<float>(quantise(k.alpha_rad, 2e-5));
      in.gamma_rad = static_cast<float>(quantise(k.gamma_rad, 1e-5));
      in.fz_n = static_cast<float>(quantise(k.fz_n, 1.0));
      in.vx_mps = static_cast<float>(quantise(k.vx_mps, 0.01));
      const mf::MfOutput<float> f = mf::evaluate(params_, in, options_);
      out[i] = {quantise(f.fx_n, 1.0), quantise(f.fy_n, 1.0), quantise(f.mz_nm, 0.05)};
    }
    return out;
  }

 private:
  mf::MfParameters<float> params_;
  mf::MfOptions options_;
};

class DelayCompensation : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing reference data: " << path;
    tir_ = tyre::load_mf_parameters(path).params;
    p_.wheel_radius_m = tir_.unloaded_radius_m;
    reference_ = mf_tyre_function(tir_);
  }

  /// Runs `m` as the rig does over CAN: in cycle n it sends wheel_inputs() and steps with the
  /// node's answer to the inputs of cycle n − 1 (delayed) or of cycle n (delay 0).
  Trace run_over_can(Manoeuvre& m, bool delayed, bool compensate) const {
    const NodeEmulation node(tir_);
    const DelayCompensator compensator(reference_);
    m.reset();
    VehicleModel model(p_, m.initial_state());
    std::array<WheelKinematics, kWheelCount> sent = model.wheel_inputs();
    std::array<WheelForces, kWheelCount> answered = node.answer(sent);
    Trace trace;
    while (!m.finished(model.state().t_s, model.state())) {
      TraceSample s;
      s.t_s = model.state().t_s;
      s.state = model.state();
      s.inputs = model.wheel_inputs();
      if (!delayed) {
        answered = node.answer(s.inputs);
        sent = s.inputs;
      }
      s.forces = compensate ? compensator.correct(answered, sent, s.inputs) : answered;
      s.controls = m.controls(s.t_s, kDt, model.state());
      model.step(s.forces, s.controls, kDt);
      trace.push_back(s);
      if (delayed) {  // the answer to this cycle's inputs arrives in the next cycle
        answered = node.answer(s.inputs);
        sent = s.inputs;
      }
    }
    return trace;
  }

  mf::MfParameters<double> tir_;
  VehicleParams p_;
  TyreFunction reference_;
};

/// Largest step-to-step change of κ of any wheel over the last 0.5 s of the trace.
double slip_chatter(const Trace& trace) {
  double out = 0.0;
  for (std::size_t n = 1; n < trace.size(); ++n) {
    if (trace[n].t_s < trace.back().t_s - 0.5) continue;
    for (std::size_t i = 0; i < kWheelCount; ++i) {
      out = std::max(out, std::fabs(trace[n].inputs[i].kappa - trace[n - 1].inputs[i].kappa));
    }
  }
  return out;
}

TEST_F(DelayCompensation, WithoutDelayItChangesNothing) {
  const DelayCompensator compensator(reference_);
  const VehicleModel model(p_, straight_running_state(p_, 20.0));
  const auto in = model.wheel_inputs();
  std::array<WheelForces, kWheelCount> answered{};
  answered[2] = {123.0, -45.0, 6.0};
  const auto out = compensator.correct(answered, in, in);
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    EXPECT_DOUBLE_EQ(out[i].fx_n, answered[i].fx_n);
    EXPECT_DOUBLE_EQ(out[i].fy_n, answered[i].fy_n);
    EXPECT_DOUBLE_EQ(out[i].mz_nm, answered[i].mz_nm);
  }
}

TEST_F(DelayCompensation, StepSteerOverCanMatchesTheInProcessRun) {
  StepSteerManoeuvre in_process(p_, reference_);
  const ManoeuvreRun reference = run_manoeuvre(in_process, p_, reference_, kDt);
  StepSteerOptions o;
  o.steer_wheel_rad = in_process.options().steer_wheel_rad;
  StepSteerManoeuvre m(p_, reference_, o);

  // Float model and quantisation, no delay: the same results.
  const Trace direct = run_over_can(m, false, false);
  // One cycle late, uncompensated: the wheel-spin loop goes into a limit cycle.
  const Trace late = run_over_can(m, true, false);
  // One cycle late, compensated.
  const Trace compensated = run_over_can(m, true, true);
  const auto r_direct = m.results(direct);
  const auto r_late = m.results(late);
  const auto r_comp = m.results(compensated);
  std::printf("  kappa chatter: in process %.2e, over CAN %.2e, late %.2e, late compensated %.2e\n",
              slip_chatter(reference.trace), slip_chatter(direct), slip_chatter(late),
              slip_chatter(compensated));
  std::printf("  ay_steady: in process %.4f, over CAN %.4f, late %.4f, late compensated %.4f\n",
              result_value(reference.results, "ay_steady"), result_value(r_direct, "ay_steady"),
              result_value(r_late, "ay_steady"), result_value(r_comp, "ay_steady"));
  EXPECT_GT(slip_chatter(late), 1e-3);
  EXPECT_LT(slip_chatter(direct), 1e-4);
  EXPECT_LT(slip_chatter(compensated), 1e-4);
  for (const char* name : {"ay_steady", "yaw_rate_steady", "sideslip_steady"}) {
    const double ref = result_value(reference.results, name);
    EXPECT_NEAR(result_value(r_direct, name), ref, 0.002 * std::fabs(ref)) << name;
    EXPECT_NEAR(result_value(r_comp, name), ref, 0.002 * std::fabs(ref)) << name;
  }
  EXPECT_NEAR(result_value(r_comp, "yaw_rate_response_time"),
              result_value(reference.results, "yaw_rate_response_time"), 0.002);
}

TEST_F(DelayCompensation, BrakingAndSineWithDwellOverCanWithDelayMatchTheInProcessRuns) {
  {
    BrakingManoeuvre m(p_, reference_);
    const ManoeuvreRun reference = run_manoeuvre(m, p_, reference_, kDt);
    const auto r = m.results(run_over_can(m, true, true));
    const double ref = result_value(reference.results, "mean_deceleration");
    EXPECT_NEAR(result_value(r, "mean_deceleration"), ref, 0.002 * ref);
    EXPECT_NEAR(result_value(r, "stopping_distance"),
                result_value(reference.results, "stopping_distance"), 0.1);
  }
  {
    SineDwellOptions o;
    o.amplitude_factor = 1.5;
    SineDwellManoeuvre m(p_, reference_, o);
    const ManoeuvreRun reference = run_manoeuvre(m, p_, reference_, kDt);
    const auto r = m.results(run_over_can(m, true, true));
    for (const char* name : {"peak_yaw_rate", "lateral_displacement_1_07"}) {
      const double ref = result_value(reference.results, name);
      EXPECT_NEAR(result_value(r, name), ref, 0.005 * std::fabs(ref)) << name;
    }
  }
}

}  // namespace
}  // namespace tread::vehicle
