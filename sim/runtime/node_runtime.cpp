#include "runtime/node_runtime.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mf/mf_fixed.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::host {

void NodeRuntime::build_forces(const contact::RigidContact& contact,
                               const contact::ContactSetup& setup, const NodeSettings& settings,
                               double y_first_mm, double y_last_mm, double step_mm) {
  const std::vector<contact::MechanicsRow> table =
      contact::mechanics_table(contact, y_first_mm, y_last_mm, step_mm, settings.materials);
  mechanics_rows_ = contact::mechanics_rows_f32(table);
  mechanics_ = rail::MechanicsTableF32{static_cast<float>(y_first_mm), static_cast<float>(step_mm),
                                       static_cast<std::uint32_t>(mechanics_rows_.size()),
                                       mechanics_rows_.data()};
  // Nadal's limit takes the profiles' flange angle, not the largest angle the table's range
  // happens to reach (the default ±12 mm table can stop short of the flange's steepest point).
  const contact::FlangeAngles flange =
      contact::profile_flange_angles(contact, std::max(std::abs(y_first_mm), std::abs(y_last_mm)));
  const rail::PolachParameters<double> p =
      contact::friction_parameters(settings.friction, settings.mu);
  force_settings_.g_mpa = static_cast<float>(settings.materials.g_mpa());
  force_settings_.polach = {static_cast<float>(p.mu0), static_cast<float>(p.a_ratio),
                            static_cast<float>(p.b_s_per_m), static_cast<float>(p.k_adhesion),
                            static_cast<float>(p.k_slip)};
  force_settings_.flange_angle_left_rad = static_cast<float>(flange.left_rad);
  force_settings_.flange_angle_right_rad = static_cast<float>(flange.right_rad);
  // A free axle spins so that it rolls without longitudinal creep at the centred position.
  const contact::ContactState centred = contact.at(0.0);
  force_settings_.r0_mm = static_cast<float>(0.5 * (centred.left.r_mm + centred.right.r_mm));
  // e0 follows the wheelset given (b2b/2 + 70 mm), as in `tread contact --load`.
  force_settings_.half_contact_base_mm = static_cast<float>(contact::half_contact_base_mm(setup));
  for (auto& f : forces_) {
    f = node::RailForceTableChannel(mechanics_, force_settings_);
  }
}

mf::MfOptions node_tyre_options(int use_mode, const std::string& side) {
  const Result<mf::MfOptions> options = mf::options_from_use_mode(use_mode);
  if (!options.ok()) {
    throw std::runtime_error("--use-mode " + std::to_string(use_mode) +
                             ": not a useMode (111..222)");
  }
  mf::MfOptions o = options.value;
  o.extras = true;  // Rl is an output
  if (side == "left") {
    o.side = mf::MountedSide::left;
  } else if (side == "right") {
    o.side = mf::MountedSide::right;
  } else if (side != "as-measured") {
    throw std::runtime_error("--side: want as-measured, left or right, not '" + side + "'");
  }
  return o;
}

NodeRuntime::NodeRuntime(const NodeSettings& settings) {
  node::NodeConfig config = settings.node;
  if (config.wheels > 0) {
    if (settings.tir.empty()) {
      throw std::runtime_error("a tyre property file (--tir) is needed for road wheels");
    }
    const tyre::MfTirParameters loaded = tyre::load_mf_parameters(settings.tir);
    params_double_ = loaded.params;
    tir_warning_ = loaded.warning;
    params_ = mf::convert_parameters<float>(params_double_);
    options_ = node_tyre_options(settings.use_mode, settings.side);
    if (settings.fixed) {
      params_fixed_ = mf::to_fixed_parameters(params_double_);
      for (auto& tyre : tyres_fixed_) {
        tyre = node::MfTyreChannelFixed(params_fixed_, options_, settings.relaxation);
      }
    } else {
      for (auto& tyre : tyres_) {
        tyre = node::MfTyreChannel(params_, options_, settings.relaxation);
      }
    }
  }
  if (config.wheelsets > 0) {
    if (settings.wheelset_profile.empty()) {
      throw std::runtime_error("wheelsets need --wheelset-profile (e.g. wheel=S1002,rail=60E1)");
    }
    const contact::ContactSetup setup = parse_wheelset_profile(settings.wheelset_profile);
    const contact::RigidContact contact = contact::build_contact(setup);
    const contact::ContactTable t = contact.table(
        -settings.wheelset_ymax_mm, settings.wheelset_ymax_mm, settings.wheelset_step_mm);
    const std::size_t n = t.y_mm.size();
    rows_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      rows_[i] = rail::ContactRowF32{
          static_cast<float>(t.r_left_mm[i]), static_cast<float>(t.r_right_mm[i]),
          static_cast<float>(t.delta_r_mm[i]), static_cast<float>(t.gamma_left_rad[i]),
          static_cast<float>(t.gamma_right_rad[i])};
    }
    table_ =
        rail::ContactTableF32{static_cast<float>(t.y_first_mm), static_cast<float>(t.y_step_mm),
                              static_cast<std::uint32_t>(n), rows_.data()};
    // In integers as the LUT generator flashes them (sim/lut/lut_generator.cpp): rounded to
    // nearest.
    const auto q = [](double v, double per_unit) {
      return static_cast<std::int32_t>(std::llround(v * per_unit));
    };
    rows_q_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      rows_q_[i] = rail::ContactRowQ{
          q(t.r_left_mm[i], rail::kQLengthPerMm), q(t.r_right_mm[i], rail::kQLengthPerMm),
          q(t.delta_r_mm[i], rail::kQLengthPerMm), q(t.gamma_left_rad[i], rail::kQAnglePerRad),
          q(t.gamma_right_rad[i], rail::kQAnglePerRad)};
    }
    table_q_ = rail::ContactTableQ{q(t.y_first_mm, rail::kQYPerMm), q(t.y_step_mm, rail::kQYPerMm),
                                   static_cast<std::uint32_t>(n), rows_q_.data()};
    // The integer table's y is in whole µm: a first y or step between them would put every row at
    // the wrong y.
    const auto whole_um = [](double mm) {
      return std::abs(mm * rail::kQYPerMm - std::round(mm * rail::kQYPerMm)) < 1e-6;
    };
    if (settings.fixed &&
        (table_q_.y_step <= 0 || !whole_um(t.y_first_mm) || !whole_um(t.y_step_mm))) {
      throw std::runtime_error(
          "wheelset contact table (NodeSettings wheelset_ymax_mm, wheelset_step_mm): the "
          "fixed-point table needs its first y and its step in whole micrometres, the step at "
          "least 1 µm");
    }
    for (auto& c : contacts_) {
      c = node::ContactTableChannel(table_);
    }
    if (config.wheelset_forces > 0) {
      if (settings.fixed) {
        throw std::runtime_error(
            "wheel-rail forces (--wheelset-forces) run in float only, not with --fixed");
      }
      build_forces(contact, setup, settings, t.y_first_mm, t.y_mm.back(), t.y_step_mm);
    }
    for (auto& c : contacts_fixed_) {
      c = node::ContactTableChannelFixed(table_q_);
    }
  }
  if (settings.fixed) {
    node_fixed_ = std::make_unique<RuntimeNodeFixed>(config, tyres_fixed_, contacts_fixed_);
  } else {
    node_ = std::make_unique<RuntimeNode>(config, tyres_, contacts_, forces_);
  }
}

}  // namespace tread::host
