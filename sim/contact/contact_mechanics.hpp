#pragma once
// From the rigid contact geometry to the elastic contact: for each wheelset displacement y and
// each wheel, the load-independent data of its (up to two) contact points — rolling radius,
// contact angle, vertical gap, Hertz shape at unit load and Kalker's coefficients — which the
// node's tables hold and the core (rail/wheel_contact.hpp) scales by the load at run time. And the
// evaluation of a whole table at a wheel load and wheelset motion for `tread contact`.

#include <optional>
#include <string>
#include <vector>

#include "contact/rigid_contact.hpp"
#include "rail/fastsim.hpp"
#include "rail/mechanics_table.hpp"
#include "rail/wheel_contact.hpp"

namespace tread::contact {

struct Material {
  double e_mpa = 210000.0;  ///< Young's modulus
  double nu = 0.3;          ///< Poisson's ratio
};

struct ContactMaterials {
  Material wheel_material;
  Material rail_material;
  /// E* of the pair (MPa).
  double e_star_mpa() const;
  /// Combined shear modulus 2 G1 G2 / (G1 + G2) (MPa).
  double g_mpa() const;
  /// Poisson's ratio for Kalker's coefficients: the mean of the two.
  double nu() const;
};

struct MechanicsSettings {
  /// A second contact point whose vertical gap exceeds this is left out (no load can close it).
  double second_point_max_gap_mm = 0.5;
  /// Lateral relative curvature floor (1/mm): a conformal point (curvature <= this) is given
  /// this curvature, i.e. a relative lateral radius of 1 / floor, and flagged.
  double min_lateral_curvature_per_mm = 1e-4;
};

/// One wheel at one y.
struct WheelMechanics {
  rail::ContactPointData<double> point[2];
  bool conformal[2] = {false, false};  ///< curvature floored (Hertz is only an approximation)
};

struct MechanicsRow {
  double y_mm = 0.0;
  WheelMechanics left;
  WheelMechanics right;
};

/// The load-independent data of one contact point.
rail::ContactPointData<double> point_mechanics(const ContactPoint& p, double vertical_gap_mm,
                                               const ContactMaterials& m,
                                               const MechanicsSettings& s, bool& conformal);

/// Both wheels at one contact state.
MechanicsRow mechanics_row(const ContactState& c, const ContactMaterials& m,
                           const MechanicsSettings& s = {});

/// y = y_min, y_min + step, ... y_max (as RigidContact::table).
std::vector<MechanicsRow> mechanics_table(const RigidContact& contact, double y_min_mm,
                                          double y_max_mm, double step_mm,
                                          const ContactMaterials& m,
                                          const MechanicsSettings& s = {});

/// The largest contact angle of any main contact point in the table, per wheel: the flange angle
/// the profiles reach (Nadal's limit for wheels on their tread).
struct FlangeAngles {
  double left_rad = 0.0;
  double right_rad = 0.0;
};
FlangeAngles flange_angles(const std::vector<MechanicsRow>& table);

/// The same over every lateral position where the wheels still meet the rails (0.1 mm apart, out
/// to ±30 mm or ±`beyond_mm` if wider), whatever range a table covers: the flange angle of the
/// profiles themselves, for Nadal's limit of a table that stops short of flange contact. The
/// contact angles of the geometry (RigidContact::at), which are the main points' of
/// mechanics_table.
FlangeAngles profile_flange_angles(const RigidContact& contact, double beyond_mm = 0.0);

/// Polach's parameters by name: "kalker" (kA = kS = 1, constant mu: Kalker's initial slope),
/// "dry" or "wet" (Polach 2005's recommended sets); mu > 0 replaces mu0. Throws
/// std::invalid_argument for another name.
rail::PolachParameters<double> friction_parameters(const std::string& name, double mu = 0.0);

/// The table in the node's float rows (rail/mechanics_table.hpp).
std::vector<rail::MechanicsRowF32> mechanics_rows_f32(const std::vector<MechanicsRow>& table);

enum class CreepLaw { polach, fastsim };

/// The wheelset's motion in track axes (y toward the left rail, yaw counter-clockwise from above)
/// and the loads, for evaluating a table.
struct WheelsetState {
  double speed_m_s = 20.0;
  double lateral_velocity_m_s = 0.0;
  double yaw_rad = 0.0;
  double yaw_rate_rad_s = 0.0;
  /// Axle spin (0: a locked wheelset); none: free rolling on the nominal radius, V / r0.
  std::optional<double> axle_spin_rad_s;
  double load_left_n = 0.0;
  double load_right_n = 0.0;
};

/// Evaluates one wheel: mirrors the motion for the right wheel, runs rail::wheel_forces (Polach)
/// or the same steps with FASTSIM at the points (constant friction mu0). Lateral forces come out
/// in the wheel's own frame (toward its field side positive).
rail::WheelForces<double> evaluate_wheel(const WheelMechanics& wheel, bool right_wheel,
                                         const WheelsetState& state, double r0_mm,
                                         double half_contact_base_mm, const ContactMaterials& m,
                                         double flange_angle_rad,
                                         const rail::PolachParameters<double>& polach, CreepLaw law,
                                         const rail::FastsimGrid& grid = {});

}  // namespace tread::contact
