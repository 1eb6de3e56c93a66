#pragma once
// Tyre-test-machine scenario: the scripted slip, load and displacement sweeps of ScriptedRig (open
// loop: the answers do not feed back), for checking the node's force curves point by point.

#include "rig/rig_scenario.hpp"
#include "rig/scripted_rig.hpp"

namespace tread::host {

class SweepScenario final : public RigScenario {
 public:
  SweepScenario(std::uint8_t wheels, std::uint8_t wheelsets, double duration_s)
      : wheels_(wheels), wheelsets_(wheelsets), duration_s_(duration_s) {}

  [[nodiscard]] std::string name() const override { return "sweep"; }
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] double duration_s() const override { return duration_s_; }
  void inputs(double t_s, proto::RigData& data) override;
  void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
               double dt_s) override;
  [[nodiscard]] std::vector<std::string> trace_columns() const override;
  void trace_values(std::vector<double>& row) const override;
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override;
  std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                          const std::filesystem::path& out_dir) const override;

 private:
  std::uint8_t wheels_;
  std::uint8_t wheelsets_;
  double duration_s_;
  ScriptedRig rig_{};
  proto::RigData seen_{};
  proto::NodeData answers_{};
  double peak_fx_n_{0.0};
  double peak_fy_n_{0.0};
};

}  // namespace tread::host
