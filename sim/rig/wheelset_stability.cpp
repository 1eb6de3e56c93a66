#include "rig/wheelset_stability.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact/contact_setup.hpp"

namespace tread::host {

WheelsetContactModel::WheelsetContactModel(const contact::RigidContact& contact,
                                           const contact::ContactMaterials& m,
                                           const rail::PolachParameters<double>& polach,
                                           double r_spin_mm, double wheel_load_n,
                                           double half_contact_base_m,
                                           const contact::FlangeAngles& flange)
    : contact_(&contact),
      materials_(m),
      polach_(polach),
      r_spin_mm_(r_spin_mm),
      wheel_load_n_(wheel_load_n),
      e0_m_(half_contact_base_m),
      flange_(flange) {}

contact::RigidContact build_wheelset_contact(const WheelsetForceSetup& setup) {
  return contact::build_contact(contact::parse_wheelset_profile(setup.wheelset_profile));
}

rail::Vector2<double> generalised_force(const proto::RailWheelOutput& left,
                                        const proto::RailWheelOutput& right,
                                        double half_contact_base_m) {
  const auto wheel = [](const proto::RailWheelOutput& o) {
    return rail::WheelContactForces<double>{static_cast<double>(o.y_n), static_cast<double>(o.fx_n),
                                            static_cast<double>(o.mz_nm)};
  };
  return rail::contact_generalised_force(wheel(left), wheel(right), half_contact_base_m);
}

namespace {

double centred_radius_mm(const contact::RigidContact& c) {
  const contact::ContactState centred = c.at(0.0);
  return 0.5 * (centred.left.r_mm + centred.right.r_mm);
}

}  // namespace

WheelsetContactModel::WheelsetContactModel(const contact::RigidContact& contact,
                                           const WheelsetForceSetup& setup,
                                           const rail::WheelsetParams<double>& params)
    : WheelsetContactModel(
          contact, setup.materials, contact::friction_parameters(setup.friction, setup.mu),
          centred_radius_mm(contact), params.wheel_load_n, params.half_contact_base_m,
          // The profiles' flange angle, not the largest one the table's ±ymax reaches.
          contact::profile_flange_angles(contact, setup.ymax_mm)) {}

rail::Vector2<double> WheelsetContactModel::force(const rail::WheelsetState<double>& s,
                                                  double speed_m_s) const {
  const contact::MechanicsRow row =
      contact::mechanics_row(contact_->at(s.q(0) * 1000.0), materials_);
  contact::WheelsetState state;
  state.speed_m_s = speed_m_s;
  state.yaw_rad = s.q(1);
  state.lateral_velocity_m_s = s.v(0);
  state.yaw_rate_rad_s = s.v(1);
  state.axle_spin_rad_s = speed_m_s / (r_spin_mm_ * 1e-3);
  state.load_left_n = wheel_load_n_;
  state.load_right_n = wheel_load_n_;
  const double e0_mm = e0_m_ * 1000.0;
  const rail::WheelForces<double> left =
      contact::evaluate_wheel(row.left, false, state, r_spin_mm_, e0_mm, materials_,
                              flange_.left_rad, polach_, contact::CreepLaw::polach);
  const rail::WheelForces<double> right =
      contact::evaluate_wheel(row.right, true, state, r_spin_mm_, e0_mm, materials_,
                              flange_.right_rad, polach_, contact::CreepLaw::polach);
  const auto wheel = [](const rail::WheelForces<double>& w) {
    const rail::WheelContactTotals<double> totals = rail::wheel_totals(w);
    return rail::WheelContactForces<double>{w.yq.y_n, totals.fx_n, totals.mz_nm};
  };
  return rail::contact_generalised_force(wheel(left), wheel(right), e0_m_);
}

WheelsetContactModel::Linearisation WheelsetContactModel::linearise(double speed_m_s) const {
  Linearisation out;
  const double hq[2] = {1e-6, 1e-6};
  const double hv[2] = {1e-5, 1e-5};
  for (int k = 0; k < 2; ++k) {
    rail::WheelsetState<double> plus;
    rail::WheelsetState<double> minus;
    plus.q(k) = hq[k];
    minus.q(k) = -hq[k];
    out.stiffness.col(k) = (force(plus, speed_m_s) - force(minus, speed_m_s)) / (2.0 * hq[k]);
    plus = minus = rail::WheelsetState<double>{};
    plus.v(k) = hv[k];
    minus.v(k) = -hv[k];
    out.damping.col(k) = (force(plus, speed_m_s) - force(minus, speed_m_s)) / (2.0 * hv[k]);
  }
  return out;
}

LinearMode least_damped_mode(const rail::WheelsetParams<double>& params,
                             const WheelsetContactModel& model, double speed_m_s) {
  const WheelsetContactModel::Linearisation lin = model.linearise(speed_m_s);
  const Eigen::Matrix4d a = rail::system_matrix(params, lin.stiffness, lin.damping);
  const rail::EigenHeapForbidden no_heap;
  const Eigen::EigenSolver<Eigen::Matrix4d> solver(a, false);
  LinearMode out;
  out.growth_rate_per_s = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const std::complex<double> e = solver.eigenvalues()(i);
    if (e.real() > out.growth_rate_per_s) {
      out.growth_rate_per_s = e.real();
      out.frequency_hz = std::abs(e.imag()) / (2.0 * std::numbers::pi);
    }
  }
  out.wavelength_m = out.frequency_hz > 0.0 ? speed_m_s / out.frequency_hz : 0.0;
  return out;
}

double linear_critical_speed(const rail::WheelsetParams<double>& params,
                             const WheelsetContactModel& model, double lo_m_s, double hi_m_s) {
  double lo = lo_m_s;
  double hi = hi_m_s;
  if (!(least_damped_mode(params, model, lo).growth_rate_per_s < 0.0) ||
      !(least_damped_mode(params, model, hi).growth_rate_per_s > 0.0)) {
    return std::nan("");
  }
  while (hi - lo > 1e-3) {
    const double mid = 0.5 * (lo + hi);
    (least_damped_mode(params, model, mid).growth_rate_per_s > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace tread::host
