#pragma once
// The rig's scenarios by name, for `tread demo --scenario` and `tread rig --scenario`.

#include <memory>
#include <string>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "contact/rigid_contact.hpp"
#include "mf/mf_options.hpp"
#include "rig/rig_scenario.hpp"

namespace tread::host {

struct ScenarioContext {
  std::filesystem::path tir;  ///< the node's tyre file (road scenarios)
  std::uint8_t wheels{4};
  std::uint8_t wheelsets{2};
  std::uint8_t wheelset_forces{0};  ///< wheelsets the node serves wheel-rail forces for
  std::string wheelset_profile;     ///< the node's wheelset profile (rail scenarios)
  std::string friction{"kalker"};   ///< the node's Polach parameters and materials
  double mu{0.0};
  contact::ContactMaterials materials{};
  double wheelset_ymax_mm{12.0};
  double wheelset_step_mm{0.1};
  double sweep_duration_s{4.0};
  double period_s{1e-3};  ///< the rig's step
  /// The node's tyre options (useMode, mounted side): the vehicle scenarios' reference run in
  /// double ("tyre in double") takes the same tyre.
  mf::MfOptions tyre_options{};
};

/// Every scenario name, in the demo's order.
std::vector<std::string> scenario_names();
/// The scenarios `tread demo` runs by default for this channel configuration.
std::vector<std::string> default_scenarios(const ScenarioContext& context);
/// Whether a scenario needs the node's wheel-rail forces (dynamic-hunting, curving).
bool needs_wheelset_forces(const std::string& name);
/// Throws std::invalid_argument for an unknown name or one the channels cannot run.
std::unique_ptr<RigScenario> make_scenario(const std::string& name, const ScenarioContext& context);
/// Every scenario of a run, built (and so checked) before the first cycle; `names` empty: the
/// defaults for the channels.
std::vector<std::unique_ptr<RigScenario>> make_scenarios(const std::vector<std::string>& names,
                                                         const ScenarioContext& context);
/// The rig's reference for the node's delta r answers: the node's contact table (same wheelset
/// profile, range and step) in double.
contact::ContactTable reference_contact_table(const ScenarioContext& context);

}  // namespace tread::host
