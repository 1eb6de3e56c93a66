#pragma once
// The suspended wheelset (rail/wheelset_model.hpp) with the same contact mechanics the node serves,
// evaluated on the host in double directly on the rigid contact (no table): the generalised
// contact forces at any state, their linearisation at the centred equilibrium, the eigenvalues of
// the linearised equations and the linear critical speed (where the least damped eigenvalue's real
// part crosses zero).

#include <complex>
#include <string>

#include "contact/contact_mechanics.hpp"
#include "proto/data_model.hpp"
#include "rail/wheelset_model.hpp"

namespace tread::host {

/// What the rig must know of the node's force channel to model it: the wheelset profile, the
/// table's range (its flange angles), Polach's parameters and the materials (the node's settings).
struct WheelsetForceSetup {
  std::string wheelset_profile;
  double ymax_mm{12.0};
  double step_mm{0.1};
  std::string friction{"kalker"};
  double mu{0.0};
  contact::ContactMaterials materials{};
};

/// The wheelset's contact from the setup's profile (throws as contact::build_contact).
contact::RigidContact build_wheelset_contact(const WheelsetForceSetup& setup);

/// The generalised contact forces from the node's answers for the two wheels (left, right).
rail::Vector2<double> generalised_force(const proto::RailWheelOutput& left,
                                        const proto::RailWheelOutput& right,
                                        double half_contact_base_m);

class WheelsetContactModel {
 public:
  /// `contact` must outlive the model. The axle spins at V / r_spin (the mean rolling radius at
  /// y = 0, as the node's force channel does); Nadal's limit at the table's flange angles.
  WheelsetContactModel(const contact::RigidContact& contact, const contact::ContactMaterials& m,
                       const rail::PolachParameters<double>& polach, double r_spin_mm,
                       double wheel_load_n, double half_contact_base_m,
                       const contact::FlangeAngles& flange);
  /// The node's force channel as `setup` configures it, for a wheelset with `params`: the axle
  /// spin radius is the mean rolling radius at y = 0, the flange angles those of the table.
  WheelsetContactModel(const contact::RigidContact& contact, const WheelsetForceSetup& setup,
                       const rail::WheelsetParams<double>& params);

  /// Generalised contact forces (F_y [N], M_z [N m]) at state s and speed V.
  [[nodiscard]] rail::Vector2<double> force(const rail::WheelsetState<double>& s,
                                            double speed_m_s) const;

  /// Derivatives of the contact forces at the centred equilibrium: with respect to (y, psi) and
  /// to (y', psi'), by central differences (steps 1e-6 m, 1e-6 rad, 1e-5 m/s, 1e-5 rad/s).
  struct Linearisation {
    rail::Matrix2<double> stiffness;
    rail::Matrix2<double> damping;
  };
  [[nodiscard]] Linearisation linearise(double speed_m_s) const;

  [[nodiscard]] double r_spin_mm() const { return r_spin_mm_; }

 private:
  const contact::RigidContact* contact_;
  contact::ContactMaterials materials_;
  rail::PolachParameters<double> polach_;
  double r_spin_mm_;
  double wheel_load_n_;
  double e0_m_;
  contact::FlangeAngles flange_;
};

/// The least damped mode of the linearised wheelset at a speed.
struct LinearMode {
  double growth_rate_per_s = 0.0;  ///< real part of its eigenvalue (> 0: unstable)
  double frequency_hz = 0.0;       ///< imaginary part / 2 pi
  double wavelength_m = 0.0;       ///< V / frequency
};
LinearMode least_damped_mode(const rail::WheelsetParams<double>& params,
                             const WheelsetContactModel& model, double speed_m_s);

/// The speed in [lo, hi] where the least damped mode's growth rate crosses zero (bisection to
/// 1e-3 m/s); NaN when it does not change sign there.
double linear_critical_speed(const rail::WheelsetParams<double>& params,
                             const WheelsetContactModel& model, double lo_m_s, double hi_m_s);

}  // namespace tread::host
