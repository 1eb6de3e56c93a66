#include "rig/demo_rig.hpp"

#include <filesystem>

#include "rig/scenario_catalogue.hpp"

namespace tread::host {
namespace {

ScenarioContext context_of(const DemoSettings& s) {
  ScenarioContext c;
  c.tir = s.node.tir;
  c.wheels = s.node.node.wheels;
  c.wheelsets = s.node.node.wheelsets;
  c.wheelset_forces = s.node.node.wheelset_forces;
  c.friction = s.node.friction;
  c.mu = s.node.mu;
  c.materials = s.node.materials;
  c.wheelset_profile = s.node.wheelset_profile;
  c.wheelset_ymax_mm = s.node.wheelset_ymax_mm;
  c.wheelset_step_mm = s.node.wheelset_step_mm;
  c.sweep_duration_s = s.sweep_duration_s;
  c.period_s = static_cast<double>(s.period_us) * 1e-6;
  return c;
}

}  // namespace

DemoRig::DemoRig(const DemoSettings& s, const NodeRuntime& runtime)
    : link_(runtime.config().layout, runtime.config().wheels, runtime.config().wheelsets,
            runtime.config().wheelset_forces),
      step_s_(static_cast<double>(s.period_us) * 1e-6) {
  const node::NodeConfig& cfg = runtime.config();
  ScenarioContext context = context_of(s);
  if (runtime.config().wheels > 0) context.tyre_options = runtime.tyre_options();
  scenarios_ = make_scenarios(s.scenarios, context);
  if (cfg.wheels > 0) {
    reference_.tyre = &runtime.tyre_parameters();
    reference_.options = runtime.tyre_options();
  }
  if (cfg.wheelsets > 0) {
    contact_reference_ = reference_contact_table(context);
    reference_.contact = &contact_reference_;
  }
  for (auto& scenario : scenarios_) {
    runners_.push_back(std::make_unique<ScenarioRunner>(
        *scenario, link_, cfg.layout, cfg.wheels, cfg.wheelsets, reference_, cfg.wheelset_forces));
  }
  std::filesystem::create_directories(s.out_dir);
}

void DemoRig::finish(const DemoSettings& s, DemoResult& result) {
  for (auto& runner : runners_) {
    ScenarioOutcome o = finish_scenario(*runner, s.out_dir, s.plot);
    result.answers.add(o.check);
    result.scenarios.push_back(std::move(o));
  }
  result.rig_frames_accepted = link_.accepted();
  result.rig_frames_rejected = link_.rejected();
  result.rig_frames_saturated = link_.saturated_frames();
}

}  // namespace tread::host
