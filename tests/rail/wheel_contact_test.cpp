// One wheel on its rail: creepages from the wheelset motion, the two-point load split, and the
// wheel's forces, Y/Q and Nadal margin.
#include "rail/wheel_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace tread::rail {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kE = 210000.0;
constexpr double kNu = 0.3;

WheelKinematics<double> rolling(double v_m_s, double r0_mm) {
  WheelKinematics<double> k;
  k.speed_m_s = v_m_s;
  k.axle_spin_rad_s = v_m_s / (r0_mm * 1e-3);
  return k;
}

ContactPointData<double> point(double r_mm, double gamma_deg, double gap_mm, double a_curv,
                               double b_curv) {
  ContactPointData<double> p;
  p.present = true;
  p.r_mm = r_mm;
  p.gamma_rad = gamma_deg * kDeg;
  p.vertical_gap_mm = gap_mm;
  p.shape = hertz_shape(a_curv, b_curv, contact_modulus_mpa(kE, kNu, kE, kNu)).value;
  p.c = kalker_coefficients(p.shape.a_unit_mm / p.shape.b_unit_mm, kNu);
  return p;
}

TEST(WheelContact, CreepagesOfTheClassicalWheelset) {
  const WheelKinematics<double> k = rolling(30.0, 460.0);
  // Free rolling on the nominal radius: no creep.
  const Creepage<double> none = point_creepage(k, 460.0, 0.0);
  EXPECT_NEAR(none.xi, 0.0, 1e-15);
  EXPECT_NEAR(none.eta, 0.0, 1e-15);
  EXPECT_NEAR(none.phi_per_mm, 0.0, 1e-18);
  // A larger radius slides backward: xi = -(r - r0) / r0; spin -sin(gamma) / r0 (1/mm).
  const Creepage<double> s = point_creepage(k, 463.0, 3.0 * kDeg);
  EXPECT_NEAR(s.xi, -3.0 / 460.0, 1e-12);
  EXPECT_NEAR(s.phi_per_mm, -std::sin(3.0 * kDeg) / 460.0, 1e-15);
  // Yaw angle and lateral velocity: eta = (v_y / V - psi) / cos(gamma).
  WheelKinematics<double> yawed = k;
  yawed.yaw_rad = 0.002;
  yawed.lateral_velocity_m_s = 0.03;
  EXPECT_NEAR(point_creepage(yawed, 460.0, 60.0 * kDeg).eta, (0.001 - 0.002) / 0.5, 1e-12);
  // Yaw rate: the wheel at e = 750 mm moves slower by psi_dot e.
  WheelKinematics<double> turning = k;
  turning.yaw_rate_rad_s = 0.1;
  EXPECT_NEAR(point_creepage(turning, 460.0, 0.0).xi, -0.1 * 0.75 / 30.0, 1e-12);
  EXPECT_NEAR(point_creepage(turning, 460.0, 0.0).phi_per_mm, 0.1 / 30.0 * 1e-3, 1e-15);
  // The right wheel sees the motion mirrored.
  EXPECT_NEAR(point_creepage(mirrored(yawed), 460.0, 0.0).eta, -(0.001 - 0.002), 1e-12);
  // Standing: no creep, no NaN.
  const Creepage<double> standing = point_creepage(rolling(0.0, 460.0), 470.0, 0.5);
  EXPECT_EQ(standing.xi, 0.0);
  EXPECT_EQ(standing.phi_per_mm, 0.0);
}

TEST(WheelContact, OnePointCarriesTheWheelLoadAlongItsNormal) {
  const ContactPointData<double> pts[2] = {point(460.0, 2.0, 0.0, 0.5 / 460.0, 0.5 / 300.0), {}};
  const NormalSplit<double> s = split_wheel_load(pts, 80000.0);
  EXPECT_NEAR(s.normal_n[0], 80000.0 / std::cos(2.0 * kDeg), 1e-9);
  EXPECT_EQ(s.normal_n[1], 0.0);
  const HertzPatch<double> patch = hertz_patch(pts[0].shape, s.normal_n[0]);
  EXPECT_NEAR(s.vertical_approach_mm, patch.approach_mm / std::cos(2.0 * kDeg), 1e-12);
}

TEST(WheelContact, TwoPointSplitBalancesTheLoad) {
  ContactPointData<double> pts[2] = {point(460.0, 2.0, 0.0, 0.5 / 460.0, 0.5 / 300.0),
                                     point(475.0, 68.0, 0.0, 0.5 / 1200.0, 0.5 / 15.0)};
  for (const double gap : {0.0, 0.01, 0.03, 0.06, 0.2}) {
    pts[1].vertical_gap_mm = gap;
    const NormalSplit<double> s = split_wheel_load(pts, 80000.0);
    const double vertical =
        s.normal_n[0] * std::cos(2.0 * kDeg) + s.normal_n[1] * std::cos(68.0 * kDeg);
    EXPECT_NEAR(vertical, 80000.0, 1e-6) << gap;
    // Both points sit at the same vertical approach, each at its own Hertz load.
    for (int i = 0; i < 2; ++i) {
      if (s.normal_n[i] > 0.0) {
        const double normal_approach =
            (s.vertical_approach_mm - pts[i].vertical_gap_mm) * std::cos(pts[i].gamma_rad);
        EXPECT_NEAR(hertz_patch(pts[i].shape, s.normal_n[i]).approach_mm, normal_approach, 1e-9);
      }
    }
  }
  // A gap wider than the tread's own approach leaves the flange unloaded.
  pts[1].vertical_gap_mm = 0.2;
  EXPECT_EQ(split_wheel_load(pts, 80000.0).normal_n[1], 0.0);
  // The flange's share grows as the gap closes.
  pts[1].vertical_gap_mm = 0.03;
  const double far = split_wheel_load(pts, 80000.0).normal_n[1];
  pts[1].vertical_gap_mm = 0.0;
  const double closed = split_wheel_load(pts, 80000.0).normal_n[1];
  EXPECT_GT(far, 0.0);
  EXPECT_GT(closed, far);
}

TEST(WheelContact, FlangeContactGivesYOverQAgainstNadal) {
  // A wheelset yawed against the rail (angle of attack 5 mrad) in flange contact at 70 deg: Y/Q
  // comes from the normal forces and the Polach lateral creep force at each point, summed.
  const ContactPointData<double> pts[2] = {point(460.5, 3.0, 0.0, 0.5 / 460.0, 0.5 / 300.0),
                                           point(475.0, 70.0, 0.0, 0.5 / 1300.0, 0.5 / 14.0)};
  WheelKinematics<double> k = rolling(20.0, 460.0);
  // Heading into the rail (positive angle of attack in the wheel's frame): the flange's lateral
  // creep force on the wheel points up the flange (T > 0), the case Nadal's limit is made for.
  k.yaw_rad = 0.005;
  const PolachParameters<double> dry{0.36, 1.0, 0.0, 1.0, 1.0};
  const double g = kE / (2.0 * (1.0 + kNu));
  const WheelForces<double> w =
      wheel_forces(pts, 60000.0, k, g, nadal_reference(70.0 * kDeg, 0.36), dry);
  double y = 0.0;
  double q = 0.0;
  for (int i = 0; i < 2; ++i) {
    const double n = w.point[i].normal_n;
    ASSERT_GT(n, 0.0);
    y += n * std::sin(pts[i].gamma_rad) - w.point[i].creep.fy_n * std::cos(pts[i].gamma_rad);
    q += n * std::cos(pts[i].gamma_rad) + w.point[i].creep.fy_n * std::sin(pts[i].gamma_rad);
    EXPECT_LE(std::hypot(w.point[i].creep.fx_n, w.point[i].creep.fy_n), 0.36 * n * (1 + 1e-12));
  }
  EXPECT_GT(w.point[1].creep.fy_n, 0.0);
  EXPECT_EQ(w.derailment_status, Status::ok);
  EXPECT_NEAR(w.yq.y_n, y, 1e-6);
  EXPECT_NEAR(w.yq.q_n, q, 1e-6);
  EXPECT_NEAR(w.derailment.y_over_q, y / q, 1e-12);
  EXPECT_NEAR(w.derailment.limit, nadal_limit(70.0 * kDeg, 0.36).value, 1e-12);
  EXPECT_NEAR(w.derailment.margin, w.derailment.limit - y / q, 1e-12);
}

TEST(WheelContact, WithoutAValidNadalReferenceThereIsNoLimit) {
  // A default (never computed) reference must not turn into a limit at mu = 0 of whatever
  // contact angle is loaded.
  const ContactPointData<double> pts[2] = {point(460.0, 40.0, 0.0, 0.5 / 460.0, 0.5 / 30.0), {}};
  const WheelForces<double> w = wheel_forces(pts, 60000.0, rolling(20.0, 460.0), 80000.0,
                                             NadalReference<double>{}, PolachParameters<double>{});
  EXPECT_EQ(w.derailment_status, Status::invalid_argument);
  EXPECT_EQ(w.derailment.limit, 0.0);
  EXPECT_EQ(nadal_reference(2.0, 0.3).status, Status::invalid_argument);  // beyond 90 deg
}

TEST(WheelContact, RandomFiniteInputsGiveFiniteForces) {
  // 20 000 random wheels (float, the node's type): any finite geometry, load, motion and friction
  // within wide bounds gives finite forces, quotient and margin.
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> u(0.0F, 1.0F);
  const auto in = [&](float lo, float hi) { return lo + (hi - lo) * u(rng); };
  for (int n = 0; n < 20000; ++n) {
    ContactPointData<float> pts[2];
    for (int i = 0; i < 2; ++i) {
      pts[i].present = i == 0 || u(rng) < 0.5F;
      pts[i].r_mm = in(300.0F, 600.0F);
      pts[i].gamma_rad = in(-0.2F, 1.45F);
      pts[i].vertical_gap_mm = i == 0 ? 0.0F : in(0.0F, 0.6F);
      const HertzShape<double> shape = hertz_shape(static_cast<double>(in(1e-4F, 2e-3F)),
                                                   static_cast<double>(in(5e-5F, 5e-2F)), 115000.0)
                                           .value;
      pts[i].shape = shape_as<float>(shape);
      pts[i].c = kalker_coefficients(static_cast<float>(shape.a_unit_mm / shape.b_unit_mm),
                                     in(0.25F, 0.3F));
    }
    WheelKinematics<float> k;
    k.speed_m_s = in(-1.0F, 150.0F);
    k.lateral_velocity_m_s = in(-3.0F, 3.0F);
    k.yaw_rad = in(-0.1F, 0.1F);
    k.yaw_rate_rad_s = in(-3.0F, 3.0F);
    k.axle_spin_rad_s = k.speed_m_s / 0.46F * in(0.5F, 1.5F);
    const PolachParameters<float> p{in(0.05F, 0.8F), in(0.1F, 1.0F), in(0.0F, 2.0F), in(0.1F, 1.0F),
                                    in(0.05F, 1.0F)};
    const WheelForces<float> w =
        wheel_forces(pts, in(-1000.0F, 250000.0F), k, 80769.0F, nadal_reference(1.2F, p.mu0), p);
    for (const PointForces<float>& pf : w.point) {
      ASSERT_TRUE(std::isfinite(pf.normal_n) && std::isfinite(pf.creep.fx_n) &&
                  std::isfinite(pf.creep.fy_n) && std::isfinite(pf.creep.mz_nmm))
          << n;
    }
    ASSERT_TRUE(std::isfinite(w.yq.y_n) && std::isfinite(w.yq.q_n) &&
                std::isfinite(w.derailment.y_over_q) && std::isfinite(w.derailment.margin))
        << n;
  }
}

TEST(WheelContact, LiftedWheelAndFloat) {
  const ContactPointData<double> pts[2] = {point(460.0, 2.0, 0.0, 0.5 / 460.0, 0.5 / 300.0), {}};
  const PolachParameters<double> p{};
  const WheelForces<double> lifted =
      wheel_forces(pts, 0.0, rolling(20.0, 460.0), 80000.0, nadal_reference(1.2, 0.36), p);
  EXPECT_EQ(lifted.derailment_status, Status::out_of_range);
  EXPECT_EQ(lifted.point[0].normal_n, 0.0);
  EXPECT_TRUE(std::isfinite(lifted.derailment.margin));

  ContactPointData<float> pf[2];
  pf[0].present = true;
  pf[0].r_mm = 460.0F;
  pf[0].gamma_rad = static_cast<float>(2.0 * kDeg);
  pf[0].shape = shape_as<float>(pts[0].shape);
  pf[0].c = kalker_coefficients(static_cast<float>(pts[0].shape.a_unit_mm / pts[0].shape.b_unit_mm),
                                0.3F);
  WheelKinematics<double> k = rolling(20.0, 459.0);
  k.yaw_rad = 0.001;
  WheelKinematics<float> kf{20.0F, 0.0F, 0.001F, 0.0F, static_cast<float>(k.axle_spin_rad_s),
                            750.0F};
  const PolachParameters<float> pfp{};
  const WheelForces<double> d =
      wheel_forces(pts, 70000.0, k, 80000.0, nadal_reference(1.2, 0.36), p);
  const WheelForces<float> f =
      wheel_forces(pf, 70000.0F, kf, 80000.0F, nadal_reference(1.2F, 0.36F), pfp);
  EXPECT_NEAR(f.point[0].creep.fx_n, d.point[0].creep.fx_n, 1e-4 * 70000.0);
  EXPECT_NEAR(f.point[0].creep.fy_n, d.point[0].creep.fy_n, 1e-4 * 70000.0);
  EXPECT_NEAR(f.derailment.y_over_q, d.derailment.y_over_q, 1e-5);
}

}  // namespace
}  // namespace tread::rail
