#pragma once
// The rig tests' set-up: the HIL demo in process (stub bus, simulated clock) on the shipped example
// tyre and a wheelset profile, one scenario list, its traces in the test's temporary directory.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "rig/hil_demo.hpp"
#include "test_dir.hpp"

namespace tread::testing {

inline std::filesystem::path rig_test_dir(const std::string& name) {
  return test_dir("rig_" + name);
}

inline host::DemoSettings demo_settings(
    const std::vector<std::string>& scenarios, const std::string& out_name,
    const std::string& wheelset_profile = "wheel=S1002,rail=60E1,cant=1:40") {
  host::DemoSettings s;
  s.node.tir = tyre_file("MagicFormula61_Parameters.tir");
  s.node.node.wheels = 4;
  s.node.node.wheelsets = 2;
  s.node.wheelset_profile = wheelset_profile;
  s.sim_clock = true;
  s.plot = false;
  s.scenarios = scenarios;
  s.out_dir = rig_test_dir(out_name);
  return s;
}

inline const host::ScenarioOutcome* find_outcome(const host::DemoResult& r,
                                                 const std::string& name) {
  for (const host::ScenarioOutcome& o : r.scenarios) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

inline double metric(const host::ScenarioOutcome& o, const std::string& name) {
  for (const host::ScenarioMetric& m : o.metrics) {
    if (m.name == name) return m.value;
  }
  return std::nan("");
}

inline std::string metric_note(const host::ScenarioOutcome& o, const std::string& name) {
  for (const host::ScenarioMetric& m : o.metrics) {
    if (m.name == name) return m.note;
  }
  return "(no metric " + name + ")";
}

}  // namespace tread::testing
