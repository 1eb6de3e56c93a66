#include "rig/scenario_catalogue.hpp"

#include <stdexcept>

#include "contact/contact_setup.hpp"
#include "rig/curving_scenario.hpp"
#include "rig/dynamic_hunting_scenario.hpp"
#include "rig/hunting_scenario.hpp"
#include "rig/sweep_scenario.hpp"
#include "rig/vehicle_scenario.hpp"

namespace tread::host {

std::vector<std::string> scenario_names() {
  return {"braking", "step-steer", "sine-dwell", "hunting", "dynamic-hunting", "curving", "sweep"};
}

std::vector<std::string> default_scenarios(const ScenarioContext& context) {
  std::vector<std::string> names;
  if (context.wheels == 4) {
    names = {"braking", "step-steer", "sine-dwell"};
  }
  if (context.wheelsets > 0) {
    names.emplace_back("hunting");
  }
  if (context.wheelsets > 0 && context.wheelset_forces > 0) {
    names.emplace_back("dynamic-hunting");
  }
  if (names.empty()) {
    names.emplace_back("sweep");
  }
  return names;
}

bool needs_wheelset_forces(const std::string& name) {
  return name == "dynamic-hunting" || name == "curving";
}

std::unique_ptr<RigScenario> make_scenario(const std::string& name,
                                           const ScenarioContext& context) {
  if (name == "sweep") {
    return std::make_unique<SweepScenario>(context.wheels, context.wheelsets,
                                           context.sweep_duration_s);
  }
  if (name == "braking" || name == "step-steer" || name == "sine-dwell") {
    if (context.wheels != 4) {
      throw std::invalid_argument("scenario '" + name + "' needs 4 road wheels (--wheels 4)");
    }
    return std::make_unique<VehicleScenario>(name, context.tir, context.period_s,
                                             context.tyre_options);
  }
  if (name == "hunting") {
    if (context.wheelsets == 0) {
      throw std::invalid_argument("scenario 'hunting' needs wheelsets (--wheelsets 1 or 2)");
    }
    HuntingSettings s;
    s.wheelsets = context.wheelsets;
    s.wheelset_profile = context.wheelset_profile;
    s.ymax_mm = context.wheelset_ymax_mm;
    s.step_mm = context.wheelset_step_mm;
    return std::make_unique<HuntingScenario>(s);
  }
  if (needs_wheelset_forces(name)) {
    if (context.wheelsets == 0 || context.wheelset_forces == 0) {
      throw std::invalid_argument("scenario '" + name +
                                  "' needs a wheelset with wheel-rail forces (--wheelsets 1 "
                                  "--wheelset-forces 1)");
    }
    WheelsetForceSetup setup;
    setup.wheelset_profile = context.wheelset_profile;
    setup.ymax_mm = context.wheelset_ymax_mm;
    setup.step_mm = context.wheelset_step_mm;
    setup.friction = context.friction;
    setup.mu = context.mu;
    setup.materials = context.materials;
    // e0 of the wheelset given (b2b/2 + 70 mm), not the standard gauge's 0.75 m.
    const double e0_m =
        contact::half_contact_base_mm(contact::parse_wheelset_profile(setup.wheelset_profile)) /
        1000.0;
    if (name == "curving") {
      CurvingSettings s;
      s.setup = setup;
      s.params.half_contact_base_m = e0_m;
      return std::make_unique<CurvingScenario>(s);
    }
    DynamicHuntingSettings s;
    s.setup = setup;
    s.params.half_contact_base_m = e0_m;
    return std::make_unique<DynamicHuntingScenario>(s);
  }
  std::string known;
  for (const std::string& n : scenario_names()) {
    known += (known.empty() ? "" : ", ") + n;
  }
  throw std::invalid_argument("unknown scenario '" + name + "' (known: " + known + ")");
}

std::vector<std::unique_ptr<RigScenario>> make_scenarios(const std::vector<std::string>& names,
                                                         const ScenarioContext& context) {
  std::vector<std::unique_ptr<RigScenario>> scenarios;
  for (const std::string& n : names.empty() ? default_scenarios(context) : names) {
    scenarios.push_back(make_scenario(n, context));
  }
  return scenarios;
}

contact::ContactTable reference_contact_table(const ScenarioContext& context) {
  return contact::build_contact(contact::parse_wheelset_profile(context.wheelset_profile))
      .table(-context.wheelset_ymax_mm, context.wheelset_ymax_mm, context.wheelset_step_mm);
}

}  // namespace tread::host
