#include "contact/contact_mechanics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rail/hertz_ellipse.hpp"

namespace tread::contact {

double ContactMaterials::e_star_mpa() const {
  return rail::contact_modulus_mpa(wheel_material.e_mpa, wheel_material.nu, rail_material.e_mpa,
                                   rail_material.nu);
}

double ContactMaterials::g_mpa() const {
  const double g1 = wheel_material.e_mpa / (2.0 * (1.0 + wheel_material.nu));
  const double g2 = rail_material.e_mpa / (2.0 * (1.0 + rail_material.nu));
  return 2.0 * g1 * g2 / (g1 + g2);
}

double ContactMaterials::nu() const {
  return 0.5 * (wheel_material.nu + rail_material.nu);
}

rail::ContactPointData<double> point_mechanics(const ContactPoint& p, double vertical_gap_mm,
                                               const ContactMaterials& m,
                                               const MechanicsSettings& s, bool& conformal) {
  rail::ContactPointData<double> out;
  out.present = true;
  out.r_mm = p.r_mm;
  out.gamma_rad = p.gamma_rad;
  out.vertical_gap_mm = vertical_gap_mm;
  // Along the rail: the wheel's radius in the contact plane r / cos(gamma), the rail straight.
  const double a_curv = 0.5 * std::cos(p.gamma_rad) / p.r_mm;
  conformal = !(p.lateral_relative_curvature_per_mm > s.min_lateral_curvature_per_mm);
  const double b_curv =
      0.5 * (conformal ? s.min_lateral_curvature_per_mm : p.lateral_relative_curvature_per_mm);
  const Result<rail::HertzShape<double>> shape = rail::hertz_shape(a_curv, b_curv, m.e_star_mpa());
  if (shape.status == Status::invalid_argument) {
    throw std::invalid_argument("contact mechanics: no Hertz contact at r = " +
                                std::to_string(p.r_mm) + " mm (check the materials)");
  }
  out.shape = shape.value;
  out.c = rail::kalker_coefficients(out.shape.a_unit_mm / out.shape.b_unit_mm, m.nu());
  return out;
}

namespace {

WheelMechanics wheel_mechanics(const WheelContact& w, const ContactMaterials& m,
                               const MechanicsSettings& s) {
  WheelMechanics out;
  const ContactPoint main{w.y_wheel_mm, w.r_mm, w.gamma_rad, w.lateral_relative_curvature_per_mm};
  out.point[0] = point_mechanics(main, 0.0, m, s, out.conformal[0]);
  if (std::isfinite(w.second_gap_mm) && w.second_gap_mm <= s.second_point_max_gap_mm) {
    out.point[1] = point_mechanics(w.second, w.second_gap_mm, m, s, out.conformal[1]);
  }
  return out;
}

}  // namespace

MechanicsRow mechanics_row(const ContactState& c, const ContactMaterials& m,
                           const MechanicsSettings& s) {
  MechanicsRow row;
  row.y_mm = c.y_mm;
  row.left = wheel_mechanics(c.left, m, s);
  row.right = wheel_mechanics(c.right, m, s);
  return row;
}

std::vector<MechanicsRow> mechanics_table(const RigidContact& contact, double y_min_mm,
                                          double y_max_mm, double step_mm,
                                          const ContactMaterials& m, const MechanicsSettings& s) {
  if (!(step_mm > 0.0) || !(y_max_mm >= y_min_mm)) {
    throw std::invalid_argument("contact mechanics table: need step > 0 and y_max >= y_min");
  }
  const auto n = static_cast<std::size_t>(std::floor((y_max_mm - y_min_mm) / step_mm + 1e-3)) + 1;
  std::vector<MechanicsRow> rows;
  rows.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    rows.push_back(mechanics_row(contact.at(y_min_mm + static_cast<double>(k) * step_mm), m, s));
  }
  return rows;
}

rail::PolachParameters<double> friction_parameters(const std::string& name, double mu) {
  rail::PolachParameters<double> p;  // "kalker"
  if (name == "dry") {
    p = {0.55, 0.40, 0.60, 1.00, 0.40};  // Polach 2005, dry rail
  } else if (name == "wet") {
    p = {0.30, 0.40, 0.20, 0.30, 0.10};  // Polach 2005, wet rail
  } else if (name != "kalker") {
    throw std::invalid_argument("friction: want kalker, dry or wet, not '" + name + "'");
  }
  if (mu > 0.0) {
    p.mu0 = mu;
  }
  return p;
}

std::vector<rail::MechanicsRowF32> mechanics_rows_f32(const std::vector<MechanicsRow>& table) {
  std::vector<rail::MechanicsRowF32> rows(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      rows[i].point[0][k] = rail::to_row_point(table[i].left.point[k]);
      rows[i].point[1][k] = rail::to_row_point(table[i].right.point[k]);
    }
  }
  return rows;
}

FlangeAngles flange_angles(const std::vector<MechanicsRow>& table) {
  FlangeAngles out;
  for (const MechanicsRow& r : table) {
    out.left_rad = std::max(out.left_rad, r.left.point[0].gamma_rad);
    out.right_rad = std::max(out.right_rad, r.right.point[0].gamma_rad);
  }
  return out;
}

FlangeAngles profile_flange_angles(const RigidContact& contact, double beyond_mm) {
  constexpr double kStep_mm = 0.1;
  const int steps = static_cast<int>(std::ceil(std::max(30.0, beyond_mm) / kStep_mm));
  FlangeAngles out;
  for (const int side : {-1, 1}) {
    for (int k = 0; k <= steps; ++k) {
      try {
        const ContactState c = contact.at(side * k * kStep_mm);
        out.left_rad = std::max(out.left_rad, c.left.gamma_rad);
        out.right_rad = std::max(out.right_rad, c.right.gamma_rad);
      } catch (const std::domain_error&) {
        break;  // the wheels no longer meet the rails further out
      }
    }
  }
  return out;
}

rail::WheelForces<double> evaluate_wheel(const WheelMechanics& wheel, bool right_wheel,
                                         const WheelsetState& state, double r0_mm,
                                         double half_contact_base_mm, const ContactMaterials& m,
                                         double flange_angle_rad,
                                         const rail::PolachParameters<double>& polach, CreepLaw law,
                                         const rail::FastsimGrid& grid) {
  rail::WheelKinematics<double> k;
  k.speed_m_s = state.speed_m_s;
  k.lateral_velocity_m_s = state.lateral_velocity_m_s;
  k.yaw_rad = state.yaw_rad;
  k.yaw_rate_rad_s = state.yaw_rate_rad_s;
  k.axle_spin_rad_s = state.axle_spin_rad_s.value_or(state.speed_m_s / (r0_mm * 1e-3));
  k.half_contact_base_mm = half_contact_base_mm;
  if (right_wheel) {
    k = rail::mirrored(k);
  }
  const double load = right_wheel ? state.load_right_n : state.load_left_n;
  const rail::NadalReference<double> nadal = rail::nadal_reference(flange_angle_rad, polach.mu0);
  if (law == CreepLaw::polach) {
    return rail::wheel_forces(wheel.point, load, k, m.g_mpa(), nadal, polach);
  }
  // FASTSIM at the same points and loads (constant friction mu0), then Y/Q the same way.
  rail::WheelForces<double> out = rail::wheel_contact(wheel.point, load, k);
  for (int i = 0; i < 2; ++i) {
    rail::PointForces<double>& p = out.point[i];
    if (p.normal_n > 0.0) {
      const rail::CreepContact<double> c{p.patch.a_mm, p.patch.b_mm, p.normal_n, m.g_mpa(),
                                         wheel.point[i].c};
      p.creep = rail::fastsim(c, p.creepage, polach.mu0, grid).force;
    }
  }
  rail::wheel_derailment(out, wheel.point, nadal);
  return out;
}

}  // namespace tread::contact
