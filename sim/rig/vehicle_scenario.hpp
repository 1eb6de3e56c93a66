#pragma once
// Road scenario: the 4-wheel vehicle model (sim/vehicle) driven through a manoeuvre with the node's
// tyre forces in the loop. Each cycle the model's wheel kinematics (slip from wheel speeds and body
// motion, loads from the load transfer) go to the node and the forces it answers advance the
// model by one period. After the run the manoeuvre's results are compared with the same manoeuvre
// run in process with the tyre model in double.

#include <memory>
#include <string>

#include "mf/mf_options.hpp"
#include "rig/rig_scenario.hpp"
#include "vehicle/manoeuvre.hpp"
#include "vehicle/vehicle_model.hpp"

namespace tread::host {

class VehicleScenario final : public RigScenario {
 public:
  /// `manoeuvre`: braking, step-steer or sine-dwell; `tir`: the node's tyre file (the vehicle's
  /// wheel radius and the manoeuvres' set-up: peak slip, steering angles). Throws
  /// std::invalid_argument for an unknown manoeuvre.
  /// `tyre_options`: the node's (useMode, mounted side), for the reference run in double.
  VehicleScenario(const std::string& manoeuvre, const std::filesystem::path& tir, double dt_s,
                  const mf::MfOptions& tyre_options = {});
  ~VehicleScenario() override;

  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] double duration_s() const override;
  [[nodiscard]] bool finished() const override;
  void inputs(double t_s, proto::RigData& data) override;
  void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
               double dt_s) override;
  [[nodiscard]] std::vector<std::string> trace_columns() const override;
  void trace_values(std::vector<double>& row) const override;
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override;
  std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                          const std::filesystem::path& out_dir) const override;

  /// The manoeuvre's results over CAN and in process (tyre in double), in the same order.
  [[nodiscard]] std::vector<vehicle::ManoeuvreResult> results() const;
  [[nodiscard]] std::vector<vehicle::ManoeuvreResult> reference_results() const;
  [[nodiscard]] const vehicle::Trace& trace() const { return trace_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  vehicle::Trace trace_;
  vehicle::TraceSample pending_{};  ///< the sample of the cycle in flight
};

}  // namespace tread::host
