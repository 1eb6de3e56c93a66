#pragma once
// The rig's half of the HIL demo, built once before the run (this allocates; the cycles do not
// need to): the scenarios, the reference the answers are checked against, the rig's end of the
// protocol and one runner per scenario. Shared by the single-threaded co-simulation on the
// simulated clock and the real-time run with the node on its own thread.

#include <memory>
#include <vector>

#include "contact/rigid_contact.hpp"
#include "proto/rig_link.hpp"
#include "rig/hil_demo.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/scenario_runner.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {

class DemoRig {
 public:
  DemoRig(const DemoSettings& settings, const NodeRuntime& runtime);
  DemoRig(const DemoRig&) = delete;
  DemoRig& operator=(const DemoRig&) = delete;

  /// One runner per scenario, in order (run one after the other on the shared link).
  [[nodiscard]] std::vector<std::unique_ptr<ScenarioRunner>>& runners() { return runners_; }
  [[nodiscard]] proto::RigLink& link() { return link_; }
  [[nodiscard]] double step_s() const { return step_s_; }

  /// After the last cycle: traces, plots and outcomes into `result` (answers, scenarios, the
  /// link's frame counters).
  void finish(const DemoSettings& settings, DemoResult& result);

 private:
  std::vector<std::unique_ptr<RigScenario>> scenarios_;
  contact::ContactTable contact_reference_;
  RigReference reference_;
  proto::RigLink link_;
  std::vector<std::unique_ptr<ScenarioRunner>> runners_;
  double step_s_;
};

}  // namespace tread::host
