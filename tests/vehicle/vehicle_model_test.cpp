#include "vehicle/vehicle_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "golden_path.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/tyre_function.hpp"

// Every allocation of this test program is counted while g_counting is set (the rig's step path
// must not allocate).
#include "allocation_counter.hpp"

using tread::testing::g_allocations;
using tread::testing::g_counting;

namespace tread::vehicle {
namespace {

constexpr double kDt = 1e-3;

std::array<WheelForces, kWheelCount> no_forces() {
  return {};
}

// ---------------------------------------------------------------------------------------------
// Load transfer: the quasi-static formulas against a moment balance written out here.

TEST(VehicleModel, WheelLoadsBalanceWeightAndPitchAndRollMoments) {
  const VehicleParams p;
  const double m = p.mass_kg;
  const double g = p.gravity_mps2;
  for (const double ax : {-9.0, -3.0, 0.0, 2.5}) {
    for (const double ay : {-4.0, 0.0, 3.0}) {
      const auto fz = wheel_loads(p, ax, ay);
      const double sum = fz[0] + fz[1] + fz[2] + fz[3];
      EXPECT_NEAR(sum, m * g, 1e-9 * m * g) << "ax " << ax << " ay " << ay;
      // Pitch: moments about the CG's y axis of the wheel loads balance the inertial force m·ax
      // acting at height h: (Fz_f·a − Fz_r·b) = −m·ax·h (braking, ax < 0, loads the front).
      const double front = fz[kFrontLeft] + fz[kFrontRight];
      const double rear = fz[kRearLeft] + fz[kRearRight];
      EXPECT_NEAR(front * p.cg_to_front_axle_m - rear * p.cg_to_rear_axle_m,
                  -m * ax * p.cg_height_m, 1e-9 * m * g);
      // Roll: Σ Fz·y = −m·ay·h, the front axle taking its roll-stiffness share.
      double roll = 0.0;
      for (std::size_t i = 0; i < kWheelCount; ++i) roll += fz[i] * p.wheel_y_m(i);
      EXPECT_NEAR(roll, -m * ay * p.cg_height_m, 1e-9 * m * g);
      const double roll_front = (fz[kFrontLeft] - fz[kFrontRight]) * 0.5 * p.track_m;
      EXPECT_NEAR(roll_front, -p.roll_stiffness_front_share * m * ay * p.cg_height_m, 1e-9 * m * g);
    }
  }
}

TEST(VehicleModel, WheelLoadsNeverNegative) {
  const VehicleParams p;
  const auto fz = wheel_loads(p, 0.0, 25.0);  // far beyond rollover: inner wheels lift
  for (const double f : fz) EXPECT_GE(f, 0.0);
  EXPECT_DOUBLE_EQ(fz[kFrontLeft], 0.0);
}

// ---------------------------------------------------------------------------------------------
// Kinematics and the transient slips, with zero tyre forces (the motion is then known exactly).

TEST(VehicleModel, StraightRunningHasNoSlipAndStaticLoads) {
  VehicleParams p;
  const VehicleModel model(p, straight_running_state(p, 25.0));
  for (const WheelKinematics& w : model.wheel_inputs()) {
    EXPECT_DOUBLE_EQ(w.kappa, 0.0);
    EXPECT_DOUBLE_EQ(w.alpha_rad, 0.0);
    EXPECT_DOUBLE_EQ(w.vx_mps, 25.0);
    EXPECT_DOUBLE_EQ(w.omega_radps * p.wheel_radius_m, 25.0);
  }
  const auto in = model.wheel_inputs();
  EXPECT_DOUBLE_EQ(in[0].fz_n, p.mass_kg * p.gravity_mps2 * 1.4 / 2.6 / 2.0);
  EXPECT_DOUBLE_EQ(in[3].fz_n, p.mass_kg * p.gravity_mps2 * 1.2 / 2.6 / 2.0);
}

TEST(VehicleModel, LongitudinalSlipRelaxesToKinematicSlipWithTimeConstantSigmaOverSpeed) {
  VehicleParams p;
  VehicleState s = straight_running_state(p, 20.0);
  s.omega_radps.fill(1.1 * 20.0 / p.wheel_radius_m);  // 10 % drive slip, held (no forces)
  VehicleModel model(p, s);
  // First order: κ'(t) = 0.1·(1 − exp(−t·vx/σ)). One time constant σ/vx = 10 ms.
  const double tau = p.relaxation_length_kappa_m / 20.0;
  const int n_tau = static_cast<int>(std::lround(tau / kDt));
  for (int n = 0; n < n_tau; ++n) model.step(no_forces(), Controls{}, kDt);
  // Backward Euler on the decay: within dt/(2τ) ≈ 5 % of the exact value after one τ.
  EXPECT_NEAR(model.wheel_inputs()[0].kappa, 0.1 * (1.0 - std::exp(-1.0)), 0.004);
  for (int n = 0; n < 20 * n_tau; ++n) model.step(no_forces(), Controls{}, kDt);
  for (const WheelKinematics& w : model.wheel_inputs()) EXPECT_NEAR(w.kappa, 0.1, 1e-9);
}

TEST(VehicleModel, LateralSlipAngleFollowsTheWheelsLateralVelocity) {
  VehicleParams p;
  VehicleState s = straight_running_state(p, 20.0);
  s.vy_mps = 1.0;  // the whole car slides to the left at 1 m/s
  VehicleModel model(p, s);
  for (int n = 0; n < 500; ++n) model.step(no_forces(), Controls{}, kDt);
  // Without forces vx, vy stay (no yaw): every wheel moves left, α = atan(vy/vx) > 0 (ISO-W).
  for (const WheelKinematics& w : model.wheel_inputs()) {
    EXPECT_NEAR(w.alpha_rad, std::atan(1.0 / 20.0), 1e-9);
  }
}

TEST(VehicleModel, SteeringTurnsTheFrontWheelAxes) {
  VehicleParams p;
  VehicleModel model(p, straight_running_state(p, 20.0));
  Controls c;
  c.steer_wheel_rad = 0.3;  // road wheels 0.02 rad left
  for (int n = 0; n < 500; ++n) model.step(no_forces(), c, kDt);
  const auto in = model.wheel_inputs();
  // The car still goes straight (no forces): the steered wheels see their centre moving to
  // their right, α = −δ; the rear wheels none.
  EXPECT_NEAR(in[kFrontLeft].alpha_rad, -0.02, 1e-9);
  EXPECT_NEAR(in[kFrontRight].alpha_rad, -0.02, 1e-9);
  EXPECT_NEAR(in[kRearLeft].alpha_rad, 0.0, 1e-12);
  EXPECT_NEAR(in[kFrontLeft].vx_mps, 20.0 * std::cos(0.02), 1e-9);
}

TEST(VehicleModel, ForceFreeBodyMovesInAStraightLineWhileItYaws) {
  // Body axes rotate with r: without forces the CG keeps its earth-fixed velocity.
  VehicleParams p;
  VehicleState s = straight_running_state(p, 20.0);
  s.yaw_rate_radps = 0.5;
  VehicleModel model(p, s);
  for (int n = 0; n < 1000; ++n) model.step(no_forces(), Controls{}, kDt);
  const VehicleState& e = model.state();
  EXPECT_NEAR(e.yaw_rad, 0.5, 1e-9);
  EXPECT_NEAR(std::hypot(e.vx_mps, e.vy_mps), 20.0, 20.0 * 1e-12);
  EXPECT_NEAR(e.x_m, 20.0, 0.01);
  EXPECT_NEAR(e.y_m, 0.0, 0.01);
  // In body axes the (earth-fixed) velocity now points 0.5 rad to the right.
  EXPECT_NEAR(std::atan2(e.vy_mps, e.vx_mps), -0.5, 1e-4);
}

TEST(VehicleModel, BrakeStopsTheWheelAndHoldsItNeverReversing) {
  VehicleParams p;
  VehicleModel model(p, straight_running_state(p, 10.0));
  Controls c;
  c.brake_torque_nm.fill(2000.0);
  // Without tyre forces the brake decelerates the wheel at 2000 N·m / 1 kg·m² and holds it.
  const double omega0 = 10.0 / p.wheel_radius_m;
  const int steps_to_stop = static_cast<int>(std::ceil(omega0 / (2000.0 * kDt)));
  for (int n = 0; n < steps_to_stop + 100; ++n) {
    model.step(no_forces(), c, kDt);
    for (const double w : model.state().omega_radps) EXPECT_GE(w, 0.0);
  }
  for (const double w : model.state().omega_radps) EXPECT_DOUBLE_EQ(w, 0.0);
}

TEST(VehicleModel, WheelSpinBalancesDriveTorqueAgainstTyreForce) {
  VehicleParams p;
  VehicleModel model(p, straight_running_state(p, 10.0));
  Controls c;
  c.drive_torque_nm.fill(300.0);
  std::array<WheelForces, kWheelCount> f{};
  for (WheelForces& w : f) w.fx_n = 300.0 / p.wheel_radius_m;  // the tyre reacts the torque
  const double omega0 = model.state().omega_radps[0];
  for (int n = 0; n < 100; ++n) model.step(f, c, kDt);
  EXPECT_NEAR(model.state().omega_radps[0], omega0, 1e-9);
  // 4 × 300/R N forward on 1500 kg for 0.1 s.
  EXPECT_NEAR(model.state().vx_mps, 10.0 + 0.1 * 4.0 * 300.0 / p.wheel_radius_m / p.mass_kg, 1e-9);
}

TEST(VehicleModel, NonFiniteForcesAreIgnored) {
  VehicleParams p;
  VehicleModel model(p, straight_running_state(p, 10.0));
  std::array<WheelForces, kWheelCount> f{};
  f[1].fx_n = std::nan("");
  f[2].fy_n = INFINITY;
  model.step(f, Controls{}, kDt);
  EXPECT_TRUE(std::isfinite(model.state().vx_mps));
  EXPECT_TRUE(std::isfinite(model.state().vy_mps));
  EXPECT_TRUE(std::isfinite(model.state().omega_radps[1]));
}

// ---------------------------------------------------------------------------------------------
// With the Magic Formula (data/tyres .tir): signs and stability at the rig's 1 ms step.

class VehicleModelMf : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing reference data: " << path;
    tir_ = tyre::load_mf_parameters(path).params;
    p_.wheel_radius_m = tir_.unloaded_radius_m;
    tyre_ = mf_tyre_function(tir_);
  }
  std::array<WheelForces, kWheelCount> forces(const VehicleModel& model) const {
    std::array<WheelForces, kWheelCount> f{};
    const auto in = model.wheel_inputs();
    for (std::size_t i = 0; i < kWheelCount; ++i) f[i] = tyre_(i, in[i]);
    return f;
  }
  /// dFx/dκ at κ = 0 (slip stiffness) by a central difference.
  double slip_stiffness(double fz_n, double vx_mps) const {
    WheelKinematics k;
    k.fz_n = fz_n;
    k.vx_mps = vx_mps;
    k.kappa = 1e-4;
    const double plus = tyre_(0, k).fx_n;
    k.kappa = -1e-4;
    const double minus = tyre_(0, k).fx_n;
    return (plus - minus) / 2e-4;
  }
  mf::MfParameters<double> tir_;
  VehicleParams p_;
  TyreFunction tyre_;
};

TEST_F(VehicleModelMf, TyreForcesOpposeTheSlip) {
  // The convention of the model (α > 0: wheel centre moving to its left; κ < 0: braking) must
  // give restoring forces with the tyre file: Fy < 0 for α > 0, Fx < 0 for κ < 0.
  WheelKinematics k;
  k.fz_n = p_.static_front_wheel_load_n();
  k.vx_mps = 20.0;
  k.alpha_rad = 0.05;
  EXPECT_LT(tyre_(0, k).fy_n, -1000.0);
  k.alpha_rad = 0.0;
  k.kappa = -0.05;
  EXPECT_LT(tyre_(0, k).fx_n, -1000.0);
}

TEST_F(VehicleModelMf, WheelTimeConstantWithoutRelaxationIsBelowTheRigPeriodAtLowSpeed) {
  // The reason for the transient slip: Iω·dω/dt = −R·Cκ·(ωR − vx)/vx has the time constant
  // Iω·vx/(Cκ·R²), shorter than the 1 ms step at low speed (explicit Euler needs dt < 2τ).
  const double fz = p_.static_front_wheel_load_n();
  for (const double vx : {2.0, 5.0, 10.0}) {
    const double c_kappa = slip_stiffness(fz, vx);
    const double tau =
        p_.wheel_spin_inertia_kgm2 * vx / (c_kappa * p_.wheel_radius_m * p_.wheel_radius_m);
    EXPECT_LT(tau, 1e-3) << "vx " << vx << " Ckappa " << c_kappa;
  }
  // With relaxation the wheel + tyre is an oscillator of ωn = sqrt(Cκ·R²/(Iω·σκ)): symplectic
  // Euler is stable for ωn·dt < 2, here well inside it.
  const double c_kappa = slip_stiffness(fz, 5.0);
  const double omega_n = std::sqrt(c_kappa * p_.wheel_radius_m * p_.wheel_radius_m /
                                   (p_.wheel_spin_inertia_kgm2 * p_.relaxation_length_kappa_m));
  EXPECT_LT(omega_n * kDt, 0.5);
}

/// Drives at vx with a constant drive torque on every wheel for `steps` at 1 ms; returns the
/// largest step-to-step change of κ (front left) over the last 100 steps.
double slip_chatter(const VehicleParams& p, const TyreFunction& tyre, double vx, int steps) {
  VehicleModel model(p, straight_running_state(p, vx));
  Controls c;
  c.drive_torque_nm.fill(100.0);
  double previous = 0.0;
  double chatter = 0.0;
  for (int n = 0; n < steps; ++n) {
    const auto in = model.wheel_inputs();
    std::array<WheelForces, kWheelCount> f{};
    for (std::size_t i = 0; i < kWheelCount; ++i) f[i] = tyre(i, in[i]);
    if (n >= steps - 100) chatter = std::max(chatter, std::fabs(in[0].kappa - previous));
    previous = in[0].kappa;
    model.step(f, c, kDt);
    EXPECT_TRUE(std::isfinite(in[0].kappa));
  }
  return chatter;
}

TEST_F(VehicleModelMf, TransientSlipKeepsTheWheelStableAtOneMillisecondAtLowSpeed) {
  // At 3 m/s the kinematic slip (no relaxation) makes the explicit wheel-spin step overshoot
  // every step (a sawtooth in κ); the transient slip settles to the steady drive slip.
  VehicleParams kinematic = p_;
  kinematic.relaxation_length_kappa_m = 0.0;
  // (The relaxed wheel is a lightly damped oscillator at low speed, ζ = vx/(2·σκ·ωn) ≈ 0.03 at
  // 3 m/s: it has settled to 1e-4 of slip per step within 1 s.)
  const double without = slip_chatter(kinematic, tyre_, 3.0, 1000);
  const double with = slip_chatter(p_, tyre_, 3.0, 1000);
  EXPECT_GT(without, 0.01);
  EXPECT_LT(with, 1e-4);
}

TEST_F(VehicleModelMf, BrakingThroughLowSpeedStaysFiniteAndBounded) {
  // Hard braking from 15 m/s with locked wheels and with a moderate brake, run on for 2 s after
  // the car has (nearly) stopped: no NaN, κ' within [−1, small], wheel speeds never negative,
  // the car never drives backwards faster than a creep.
  for (const double brake_nm : {5000.0, 800.0}) {
    VehicleModel model(p_, straight_running_state(p_, 15.0));
    Controls c;
    c.brake_torque_nm.fill(brake_nm);
    for (int n = 0; n < 6000; ++n) {
      const auto in = model.wheel_inputs();
      for (const WheelKinematics& w : in) {
        ASSERT_TRUE(std::isfinite(w.kappa) && std::isfinite(w.alpha_rad) && std::isfinite(w.fz_n))
            << "step " << n;
        ASSERT_GE(w.kappa, -1.0 - 1e-9) << "step " << n;
        ASSERT_LE(w.kappa, 0.05) << "step " << n;
        ASSERT_GE(w.omega_radps, 0.0);
      }
      model.step(forces(model), c, kDt);
      ASSERT_TRUE(std::isfinite(model.state().vx_mps));
      ASSERT_GT(model.state().vx_mps, -0.1) << "step " << n;
    }
    EXPECT_LT(std::fabs(model.state().vx_mps), 0.1) << "brake " << brake_nm;
  }
}

TEST_F(VehicleModelMf, StepPathDoesNotAllocate) {
  // The counter works: one deliberate allocation is seen.
  g_allocations = 0;
  g_counting = true;
  ::operator delete(::operator new(8));  // a call, not a new-expression: never elided
  g_counting = false;
  ASSERT_GE(g_allocations.load(), 1U);
  // wheel_inputs → tyre (the in-process Magic Formula) → step, 30 000 cycles of a gentle weave.
  VehicleModel model(p_, straight_running_state(p_, 20.0));
  Controls c;
  g_allocations = 0;
  g_counting = true;
  for (int n = 0; n < 30000; ++n) {
    c.steer_wheel_rad = 0.2 * std::sin(0.002 * n);
    c.drive_torque_nm.fill(50.0);
    const auto in = model.wheel_inputs();
    std::array<WheelForces, kWheelCount> f{};
    for (std::size_t i = 0; i < kWheelCount; ++i) f[i] = tyre_(i, in[i]);
    model.step(f, c, kDt);
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_TRUE(std::isfinite(model.state().x_m));
}

}  // namespace
}  // namespace tread::vehicle
