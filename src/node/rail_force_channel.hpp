#pragma once
// A wheelset's wheel-rail forces on a precomputed contact mechanics table
// (rail/mechanics_table.hpp): per cycle the contact points at the wheelset's displacement, then per
// wheel the load split, creepages from the wheelset motion, Polach's creep forces, Y/Q and the
// Nadal margin (rail/wheel_contact.hpp). Float, no heap.
//
// Outputs per wheel: Fx along the track (sum over the contact points), Y (rail on wheel, toward the
// track centre) and Q, the spin moment in N m (sum over the points, in the wheel's own frame), the
// normal forces of the two points, Y/Q and the margin to Nadal's limit.

#include "node/channels.hpp"
#include "rail/mechanics_table.hpp"
#include "rail/wheel_contact.hpp"

namespace tread::node {

struct RailForceSettings {
  float g_mpa{80769.0F};  ///< combined shear modulus (steel on steel: E 210 GPa, nu 0.3)
  rail::PolachParameters<float> polach{};
  float flange_angle_left_rad{1.2217F};  ///< the profiles' flange angles (Nadal's limit)
  float flange_angle_right_rad{1.2217F};
  float r0_mm{460.0F};                 ///< nominal rolling radius: free-rolling axle spin V / r0
  float half_contact_base_mm{750.0F};  ///< e0
};

class RailForceTableChannel {
 public:
  RailForceTableChannel() = default;
  /// The table's rows must outlive the channel.
  RailForceTableChannel(const rail::MechanicsTableF32& table,
                        const RailForceSettings& settings) noexcept
      : table_(table),
        settings_(settings),
        nadal_left_(rail::nadal_reference(settings.flange_angle_left_rad, settings.polach.mu0)),
        nadal_right_(rail::nadal_reference(settings.flange_angle_right_rad, settings.polach.mu0)) {}

  RailForceResult evaluate(const proto::WheelsetInput& in) const noexcept {
    RailForceResult out;
    const Result<rail::WheelsetContactPoints> points = rail::lookup(table_, in.lateral_mm);
    if (points.status == Status::invalid_argument) {
      out.clamped = true;
      return out;
    }
    out.clamped = points.status == Status::out_of_range;
    rail::WheelKinematics<float> k;
    k.speed_m_s = in.speed_mps;
    k.lateral_velocity_m_s = in.lateral_velocity_mps;
    k.yaw_rad = in.yaw_valid ? in.yaw_rad : 0.0F;
    k.yaw_rate_rad_s = in.yaw_rate_radps;
    k.axle_spin_rad_s = in.speed_mps / (settings_.r0_mm * 1e-3F);
    k.half_contact_base_mm = settings_.half_contact_base_mm;
    fill(out.wheel[0], rail::wheel_forces(points.value.wheel[0], in.load_left_n, k, settings_.g_mpa,
                                          nadal_left_, settings_.polach));
    fill(out.wheel[1], rail::wheel_forces(points.value.wheel[1], in.load_right_n, rail::mirrored(k),
                                          settings_.g_mpa, nadal_right_, settings_.polach));
    return out;
  }

 private:
  static void fill(RailWheelForces& out, const rail::WheelForces<float>& w) noexcept {
    const rail::WheelContactTotals<float> totals = rail::wheel_totals(w);
    out.fx_n = totals.fx_n;
    out.y_n = w.yq.y_n;
    out.q_n = w.yq.q_n;
    out.mz_nm = totals.mz_nm;
    out.n1_n = w.point[0].normal_n;
    out.n2_n = w.point[1].normal_n;
    out.y_over_q = w.derailment.y_over_q;
    out.nadal_margin = w.derailment.margin;
    out.lifted = w.derailment_status == Status::out_of_range;
  }

  rail::MechanicsTableF32 table_{};
  RailForceSettings settings_{};
  rail::NadalReference<float> nadal_left_{};
  rail::NadalReference<float> nadal_right_{};
};

static_assert(RailForceChannel<RailForceTableChannel>);

}  // namespace tread::node
