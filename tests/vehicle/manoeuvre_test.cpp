// The manoeuvres run end to end against the Magic Formula (MagicFormula61_Parameters.tir), and
// their traces are checked against physics computed here from the trace's raw quantities (tyre
// forces, positions, velocities) and from the tyre model, not from the model's own results.
#include "vehicle/manoeuvre.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "golden_path.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/manoeuvre_runner.hpp"

namespace tread::vehicle {
namespace {

constexpr double kDt = 1e-3;

struct Setup {
  VehicleParams params;
  TyreFunction tyre;
};

const Setup& setup() {
  static const Setup s = [] {
    Setup out;
    const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
    if (!std::filesystem::exists(path)) return out;  // each test asserts the file first
    const tyre::MfTirParameters tir = tyre::load_mf_parameters(path);
    out.params.wheel_radius_m = tir.params.unloaded_radius_m;
    out.tyre = mf_tyre_function(tir.params);
    return out;
  }();
  return s;
}

void assert_refdata() {
  const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing reference data: " << path;
}

void record(const std::vector<ManoeuvreResult>& results) {
  for (const ManoeuvreResult& r : results) {
    ::testing::Test::RecordProperty(r.name, std::to_string(r.value) + " " + r.unit);
    std::printf("  %-28s %12.5g %s\n", r.name.c_str(), r.value, r.unit.c_str());
  }
}

/// Body-axis sums of the trace sample's tyre forces (rotated by the steer angle they were computed
/// at) and their yaw moment about the CG.
struct BodyForces {
  double fx_n{0.0}, fy_n{0.0}, mz_nm{0.0}, fy_front_n{0.0};
};
BodyForces body_forces(const VehicleParams& p, const TraceSample& s) {
  BodyForces b;
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const double delta = i < 2 ? s.state.steer_rad : 0.0;
    const double fx = s.forces[i].fx_n;
    const double fy = s.forces[i].fy_n;
    const double fxb = fx * std::cos(delta) - fy * std::sin(delta);
    const double fyb = fx * std::sin(delta) + fy * std::cos(delta);
    const double x = i < 2 ? p.cg_to_front_axle_m : -p.cg_to_rear_axle_m;
    const double y = i % 2 == 0 ? 0.5 * p.track_m : -0.5 * p.track_m;
    b.fx_n += fxb;
    b.fy_n += fyb;
    b.mz_nm += x * fyb - y * fxb + s.forces[i].mz_nm;
    if (i < 2) b.fy_front_n += fyb;
  }
  return b;
}

/// max over κ ∈ [−1, 0] of the braking force −Fx at load fz_n and slip angle alpha_rad (a plain
/// scan at 0.0005). (With this .tir the combined-slip weighting makes |Fx| at a small α up to
/// 0.01 % larger than the pure-slip peak, so the sample's α is kept.)
double max_braking_force(const TyreFunction& tyre, double fz_n, double alpha_rad, double vx_mps) {
  WheelKinematics k;
  k.fz_n = fz_n;
  k.alpha_rad = alpha_rad;
  k.vx_mps = vx_mps;
  double best = 0.0;
  for (int j = 0; j <= 2000; ++j) {
    k.kappa = -0.0005 * j;
    best = std::max(best, -tyre(0, k).fx_n);
  }
  return best;
}

double braking_force_at(const TyreFunction& tyre, double kappa, double fz_n, double vx_mps) {
  WheelKinematics k;
  k.fz_n = fz_n;
  k.vx_mps = vx_mps;
  k.kappa = kappa;
  return -tyre(0, k).fx_n;
}

/// Samples of a braking trace between 80 % and 10 % of the initial speed (indices n with n + 1 in
/// the trace).
std::vector<std::size_t> braking_window(const Trace& trace) {
  const double v0 = trace.front().state.vx_mps;
  std::vector<std::size_t> out;
  for (std::size_t n = 0; n + 1 < trace.size(); ++n) {
    const double v = trace[n].state.vx_mps;
    if (v <= 0.8 * v0 && v >= 0.1 * v0) out.push_back(n);
  }
  return out;
}

/// Kinematic longitudinal acceleration over the step n → n + 1 (from the velocities only).
double ax_kinematic(const Trace& trace, std::size_t n) {
  const VehicleState& a = trace[n].state;
  const VehicleState& b = trace[n + 1].state;
  return (b.vx_mps - a.vx_mps) / (b.t_s - a.t_s) - a.yaw_rate_radps * a.vy_mps;
}

const ManoeuvreRun& braking_run(bool abs) {
  static const ManoeuvreRun with_abs = [] {
    BrakingManoeuvre m(setup().params, setup().tyre);
    return run_manoeuvre(m, setup().params, setup().tyre, kDt);
  }();
  static const ManoeuvreRun without_abs = [] {
    BrakingOptions o;
    o.abs = false;
    BrakingManoeuvre m(setup().params, setup().tyre, o);
    return run_manoeuvre(m, setup().params, setup().tyre, kDt);
  }();
  return abs ? with_abs : without_abs;
}

// ---------------------------------------------------------------------------------------------
// Straight-line braking

TEST(Braking, WithAbsDecelerationIsJustBelowThePeakFrictionOfTheTyre) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  const ManoeuvreRun& run = braking_run(true);
  record(run.results);
  const Trace& t = run.trace;
  const std::vector<std::size_t> window = braking_window(t);
  ASSERT_GT(window.size(), 1000U);
  // The tyre's peak friction at the loads of the run (every 50th sample of the window), summed
  // over the wheels: the largest deceleration the tyres can give, and the kinematic deceleration
  // (from the velocities) never above it.
  double bound_sum = 0.0;
  double decel_sum = 0.0;
  int n_bound = 0;
  for (std::size_t k = 0; k < window.size(); k += 50) {
    const std::size_t n = window[k];
    double force = 0.0;
    for (std::size_t i = 0; i < kWheelCount; ++i) {
      force += max_braking_force(setup().tyre, t[n].inputs[i].fz_n, t[n].inputs[i].alpha_rad,
                                 t[n].inputs[i].vx_mps);
    }
    const double bound = force / p.mass_kg;
    const double decel = -ax_kinematic(t, n);
    // (1e-5: the body axes' rotation r·vy in the kinematic deceleration.)
    EXPECT_LE(decel, bound * (1.0 + 1e-5)) << "t " << t[n].t_s;
    bound_sum += bound;
    decel_sum += decel;
    ++n_bound;
  }
  const double bound = bound_sum / n_bound;
  const double mean_decel = result_value(run.results, "mean_deceleration");
  std::printf("  peak-friction deceleration %.4f m/s^2 (mu_peak·g at the run's loads)\n", bound);
  EXPECT_LE(mean_decel, bound);
  EXPECT_GE(mean_decel, 0.97 * bound);
  // The reported mean (over distance) agrees with the mean of the kinematic deceleration (over
  // time): the deceleration is nearly constant.
  EXPECT_NEAR(mean_decel, decel_sum / n_bound, 0.01 * mean_decel);
  // Plausible stopping distance: at least v0²/(2·a), at most that plus the pedal ramp at v0.
  const double v0 = t.front().state.vx_mps;
  const double s = result_value(run.results, "stopping_distance");
  EXPECT_GE(s, v0 * v0 / (2.0 * mean_decel));
  EXPECT_LE(s, v0 * v0 / (2.0 * mean_decel) + v0 * 0.2);
}

TEST(Braking, LockedWheelsDecelerateAtTheSlidingFriction) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  const ManoeuvreRun& run = braking_run(false);
  record(run.results);
  const Trace& t = run.trace;
  const std::vector<std::size_t> window = braking_window(t);
  ASSERT_GT(window.size(), 1000U);
  double sliding_sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < window.size(); k += 50) {
    const std::size_t n = window[k];
    double force = 0.0;
    for (std::size_t i = 0; i < kWheelCount; ++i) {
      EXPECT_DOUBLE_EQ(t[n].state.omega_radps[i], 0.0) << "wheel " << i << " not locked";
      force += braking_force_at(setup().tyre, -1.0, t[n].state.fz_n[i], t[n].state.vx_mps);
    }
    sliding_sum += force / p.mass_kg;
    ++count;
  }
  const double sliding = sliding_sum / count;
  const double mean_decel = result_value(run.results, "mean_deceleration");
  std::printf("  sliding-friction deceleration %.4f m/s^2 (|Fx(kappa = -1)|/m)\n", sliding);
  EXPECT_NEAR(mean_decel, sliding, 0.01 * sliding);
  // ABS stops shorter than locked wheels.
  EXPECT_LT(result_value(braking_run(true).results, "stopping_distance"),
            result_value(run.results, "stopping_distance"));
}

TEST(Braking, LoadTransferFollowsTheDeceleration) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  const double l = p.wheelbase_m();
  const double static_front = p.mass_kg * p.gravity_mps2 * p.cg_to_rear_axle_m / l;
  double max_transfer = 0.0;
  for (const bool abs : {true, false}) {
    const Trace& t = braking_run(abs).trace;
    for (std::size_t n = 0; n + 1 < t.size(); ++n) {
      const auto& fz = t[n + 1].state.fz_n;
      ASSERT_NEAR(fz[0] + fz[1] + fz[2] + fz[3], p.mass_kg * p.gravity_mps2, 1e-6) << n;
      // The load of step n + 1 comes from the deceleration of step n (explicit transfer).
      const double expected_front =
          static_front - p.mass_kg * ax_kinematic(t, n) * p.cg_height_m / l;
      ASSERT_NEAR(fz[0] + fz[1], expected_front, 1.0) << "t " << t[n].t_s;
      max_transfer = std::max(max_transfer, fz[0] + fz[1] - static_front);
    }
  }
  // About m·μ·g·h/L: a real transfer took place.
  EXPECT_GT(max_transfer, 3000.0);
}

// ---------------------------------------------------------------------------------------------
// Step steer

const ManoeuvreRun& step_steer_run() {
  static const ManoeuvreRun run = [] {
    StepSteerManoeuvre m(setup().params, setup().tyre);
    return run_manoeuvre(m, setup().params, setup().tyre, kDt);
  }();
  return run;
}

TEST(StepSteer, SteadyStateCorneringBalancesForcesAndMoments) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  const ManoeuvreRun& run = step_steer_run();
  record(run.results);
  const Trace& t = run.trace;
  ASSERT_GT(t.size(), 3000U);
  const double t_end = t.back().t_s;
  double ay_path_sum = 0.0, fy_sum = 0.0, vxr_sum = 0.0, mz_sum = 0.0, fy_front_sum = 0.0;
  double vx_min = 1e9, vx_max = -1e9;
  int count = 0;
  for (std::size_t n = 1; n + 1 < t.size(); ++n) {
    if (t[n].t_s < t_end - 0.5) continue;
    // Acceleration of the CG from its path (second difference of the earth-fixed position),
    // turned into body axes with the yaw angle.
    const double ax_e =
        (t[n + 1].state.x_m - 2.0 * t[n].state.x_m + t[n - 1].state.x_m) / (kDt * kDt);
    const double ay_e =
        (t[n + 1].state.y_m - 2.0 * t[n].state.y_m + t[n - 1].state.y_m) / (kDt * kDt);
    const double psi = t[n].state.yaw_rad;
    ay_path_sum += -std::sin(psi) * ax_e + std::cos(psi) * ay_e;
    const BodyForces b = body_forces(p, t[n]);
    fy_sum += b.fy_n;
    mz_sum += b.mz_nm;
    fy_front_sum += b.fy_front_n;
    vxr_sum += t[n].state.vx_mps * t[n].state.yaw_rate_radps;
    vx_min = std::min(vx_min, t[n].state.vx_mps);
    vx_max = std::max(vx_max, t[n].state.vx_mps);
    ++count;
  }
  ASSERT_GT(count, 400);
  const double ay_path = ay_path_sum / count;
  const double fy = fy_sum / count;
  std::printf("  path ay %.4f m/s^2, sum Fy/m %.4f m/s^2, vx*r %.4f m/s^2, yaw moment %.2f N m\n",
              ay_path, fy / p.mass_kg, vxr_sum / count, mz_sum / count);
  // Lateral force balance: m·ay (from the path) = ΣFy in body axes.
  EXPECT_NEAR(p.mass_kg * ay_path, fy, 0.01 * std::fabs(fy));
  // Kinematics: ay = vx·r at steady state.
  EXPECT_NEAR(ay_path, vxr_sum / count, 0.01 * std::fabs(ay_path));
  // Yaw moment balance: the net moment is ~0 against the front axle's moment a·Fy_front.
  EXPECT_LT(std::fabs(mz_sum / count),
            0.01 * p.cg_to_front_axle_m * std::fabs(fy_front_sum / count));
  // The target: 4 m/s² to the left (positive steer → left turn → positive ay and r).
  EXPECT_NEAR(result_value(run.results, "ay_steady"), 4.0, 0.04);
  EXPECT_NEAR(ay_path, 4.0, 0.06);
  EXPECT_GT(result_value(run.results, "yaw_rate_steady"), 0.0);
  EXPECT_GT(result_value(run.results, "steer_wheel_angle"), 0.0);
  // Speed held by the controller.
  const double v = setup().params.mass_kg > 0.0 ? 80.0 / 3.6 : 0.0;
  EXPECT_GT(vx_min, v - 0.1);
  EXPECT_LT(vx_max, v + 0.1);
}

TEST(StepSteer, TransientMetricsArePlausible) {
  assert_refdata();
  const ManoeuvreRun& run = step_steer_run();
  // Passenger cars at 80 km/h: yaw-rate response times of about 0.1…0.4 s, overshoot 0…30 %.
  const double response = result_value(run.results, "yaw_rate_response_time");
  EXPECT_GT(response, 0.05);
  EXPECT_LT(response, 0.5);
  const double overshoot = result_value(run.results, "yaw_rate_overshoot");
  EXPECT_GE(overshoot, 0.0);
  EXPECT_LT(overshoot, 30.0);
  // Steer angle above the kinematic (Ackermann) one L·ay/v² (positive understeer gradient or
  // nearly neutral), and not absurdly far above it.
  const VehicleParams& p = setup().params;
  const double v = 80.0 / 3.6;
  const double kinematic = p.wheelbase_m() * 4.0 / (v * v) * p.steering_ratio;
  const double steer = result_value(run.results, "steer_wheel_angle");
  EXPECT_GT(steer, 0.9 * kinematic);
  EXPECT_LT(steer, 2.0 * kinematic);
}

TEST(StepSteer, InTheLinearRangeTheSteadyStateIsTheSingleTrackModels) {
  // At 1 m/s² the tyres are linear: the steady state of the 4-wheel model must be the linear
  // single-track model's, with the axle cornering stiffnesses C and pneumatic trails t of the tyre
  // at the static loads (central differences of Fy(α) and Mz(α) here). The aligning moments
  // move the axle forces back by t: force balance Fy_f + Fy_r = m·ay, moment balance
  // (a − t_f)·Fy_f = (b + t_r)·Fy_r, and δ = L/R + Fy_f/C_f − Fy_r/C_r with R = v²/ay.
  assert_refdata();
  const VehicleParams& p = setup().params;
  const double v = 80.0 / 3.6;
  const double ay = 1.0;
  struct Axle {
    double stiffness_nprad, trail_m;
  };
  const auto axle = [&](double fz) {
    WheelKinematics k;
    k.fz_n = fz;
    k.vx_mps = v;
    k.alpha_rad = 1e-3;
    const WheelForces plus = setup().tyre(0, k);
    k.alpha_rad = -1e-3;
    const WheelForces minus = setup().tyre(0, k);
    const double dfy = plus.fy_n - minus.fy_n;
    return Axle{2.0 * std::fabs(dfy) / 2e-3, -(plus.mz_nm - minus.mz_nm) / dfy};
  };
  const double l = p.wheelbase_m();
  const Axle front = axle(p.static_front_wheel_load_n());
  const Axle rear = axle(p.static_rear_wheel_load_n());
  const double arm_front = p.cg_to_front_axle_m - front.trail_m;
  const double arm_rear = p.cg_to_rear_axle_m + rear.trail_m;
  const double fy_front = p.mass_kg * ay * arm_rear / (arm_front + arm_rear);
  const double fy_rear = p.mass_kg * ay * arm_front / (arm_front + arm_rear);
  const double delta =
      l * ay / (v * v) + fy_front / front.stiffness_nprad - fy_rear / rear.stiffness_nprad;
  std::printf("  axle C front %.0f N/rad, rear %.0f N/rad; trail front %.4f m, rear %.4f m\n",
              front.stiffness_nprad, rear.stiffness_nprad, front.trail_m, rear.trail_m);
  StepSteerOptions o;
  o.steer_wheel_rad = delta * p.steering_ratio;
  StepSteerManoeuvre m(p, setup().tyre, o);
  const ManoeuvreRun run = run_manoeuvre(m, p, setup().tyre, kDt);
  const double ay_model = result_value(run.results, "ay_steady");
  const double r_model = result_value(run.results, "yaw_rate_steady");
  std::printf("  single track: steer %.5f rad for 1 m/s^2; model ay %.4f m/s^2, r %.5f rad/s\n",
              o.steer_wheel_rad, ay_model, r_model);
  EXPECT_NEAR(ay_model, ay, 0.01 * ay);
  EXPECT_NEAR(r_model, ay / v, 0.01 * ay / v);
}

// ---------------------------------------------------------------------------------------------
// Sine with dwell

TEST(SineDwell, SteeringFollowsTheStandardsProfile) {
  VehicleParams p;
  SineDwellOptions o;
  o.amplitude_rad = 2.0;
  const SineDwellManoeuvre m(p, TyreFunction{}, o);
  const double period = 1.0 / 0.7;
  EXPECT_DOUBLE_EQ(m.steer_wheel_rad(0.49), 0.0);
  EXPECT_NEAR(m.steer_wheel_rad(0.5 + 0.25 * period), 2.0, 1e-12);  // first peak, left
  EXPECT_NEAR(m.steer_wheel_rad(0.5 + 0.5 * period), 0.0, 1e-12);
  EXPECT_NEAR(m.steer_wheel_rad(0.5 + 0.75 * period), -2.0, 1e-9);  // second peak: dwell
  EXPECT_DOUBLE_EQ(m.steer_wheel_rad(0.5 + 0.75 * period + 0.49), -2.0);
  EXPECT_NEAR(m.steer_wheel_rad(0.5 + 0.75 * period + 0.5 + 0.125 * period),
              -2.0 * std::sin(std::numbers::pi / 4.0), 1e-9);
  EXPECT_DOUBLE_EQ(m.end_of_steer_s(), 0.5 + period + 0.5);
  EXPECT_DOUBLE_EQ(m.steer_wheel_rad(m.end_of_steer_s() + 0.01), 0.0);
  EXPECT_GE(m.duration_s(), m.end_of_steer_s() + 1.75);
}

TEST(SineDwell, DefaultAmplitudeIsSixAndAHalfTimesTheSteerOfPointThreeG) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  const SineDwellManoeuvre m(p, setup().tyre);
  const double delta_03g = m.options().amplitude_rad / 6.5;
  StepSteerOptions o;
  o.steer_wheel_rad = delta_03g;
  StepSteerManoeuvre step(p, setup().tyre, o);
  const ManoeuvreRun run = run_manoeuvre(step, p, setup().tyre, kDt);
  EXPECT_NEAR(result_value(run.results, "ay_steady"), 0.3 * p.gravity_mps2,
              0.01 * 0.3 * p.gravity_mps2);
}

TEST(SineDwell, RunsAndReportsTheStandardsMetrics) {
  assert_refdata();
  const VehicleParams& p = setup().params;
  SineDwellManoeuvre m(p, setup().tyre);
  const ManoeuvreRun run = run_manoeuvre(m, p, setup().tyre, kDt);
  record(run.results);
  for (const TraceSample& s : run.trace) {
    ASSERT_TRUE(std::isfinite(s.state.vx_mps) && std::isfinite(s.state.yaw_rate_radps));
  }
  ASSERT_GE(run.trace.back().t_s, m.end_of_steer_s() + 1.75);
  for (const ManoeuvreResult& r : run.results) EXPECT_TRUE(std::isfinite(r.value)) << r.name;
  // The standard's responsiveness criterion (≥ 1.83 m at 1.07 s) needs no ESC: the car turns.
  EXPECT_GT(result_value(run.results, "lateral_displacement_1_07"), 1.83);
  EXPECT_LT(result_value(run.results, "peak_yaw_rate"), 0.0);  // left first → reversal to the right
}

TEST(SineDwell, InTheLinearRangeTheYawRateDecaysAsTheStandardAsks) {
  // At 1.5 × δ0.3g (the standard's first amplitude) the tyres stay well below saturation and the
  // (stable) car's yaw rate settles: the stability criteria < 35 % at 1.00 s, < 20 % at 1.75 s.
  assert_refdata();
  const VehicleParams& p = setup().params;
  SineDwellOptions o;
  o.amplitude_factor = 1.5;
  SineDwellManoeuvre m(p, setup().tyre, o);
  const ManoeuvreRun run = run_manoeuvre(m, p, setup().tyre, kDt);
  record(run.results);
  EXPECT_LT(std::fabs(result_value(run.results, "yaw_rate_ratio_1_00")), 35.0);
  EXPECT_LT(std::fabs(result_value(run.results, "yaw_rate_ratio_1_75")), 20.0);
}

TEST(Manoeuvres, FactoryKnowsTheThreeNames) {
  assert_refdata();
  for (const char* name : {"braking", "step-steer", "sine-dwell"}) {
    const auto m = make_manoeuvre(name, setup().params, setup().tyre);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_EQ(m->name(), name);
    EXPECT_LE(m->duration_s(), 6.0);
  }
  EXPECT_EQ(make_manoeuvre("donut", setup().params, setup().tyre), nullptr);
}

}  // namespace
}  // namespace tread::vehicle
