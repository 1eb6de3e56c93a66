#pragma once
// A rig scenario: what the rig drives through the node, cycle by cycle. Each cycle the rig asks the
// scenario for the inputs (from its current state), sends them, and hands the node's answers back
// so the scenario advances its model by one period (forces held over the step). The same scenario
// runs on the in-process bus (tread demo) and as its own process over SocketCAN (tread rig), and in
// lockstep with the node both give the same trace.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "proto/data_model.hpp"

namespace tread::host {

/// A named result of a scenario (e.g. "mean deceleration", 9.1, "m/s^2").
struct ScenarioMetric {
  std::string name;
  double value{0.0};
  std::string unit;
  std::string note;  ///< how it compares (target, reference)
};

class RigScenario {
 public:
  virtual ~RigScenario() = default;
  RigScenario() = default;
  RigScenario(const RigScenario&) = delete;
  RigScenario& operator=(const RigScenario&) = delete;

  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual std::string description() const = 0;
  /// Upper bound of the simulated time; finished() may end it earlier.
  [[nodiscard]] virtual double duration_s() const = 0;
  [[nodiscard]] virtual bool finished() const { return false; }

  /// Fills the channels this scenario drives (others stay as they are).
  virtual void inputs(double t_s, proto::RigData& data) = 0;
  /// The node's answers to the inputs of this cycle (`inputs_seen`: what the node decoded, after
  /// quantisation): advance the model by `dt_s`.
  virtual void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
                       double dt_s) = 0;

  /// Trace columns (with units in their names) and the values after the last advance().
  [[nodiscard]] virtual std::vector<std::string> trace_columns() const = 0;
  virtual void trace_values(std::vector<double>& row) const = 0;

  /// Results after the run.
  [[nodiscard]] virtual std::vector<ScenarioMetric> metrics() const = 0;

  /// Writes PNG plots from the scenario's trace CSV (columns as trace_columns(), after "t_s");
  /// returns the files written.
  virtual std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                                  const std::filesystem::path& out_dir) const = 0;
};

}  // namespace tread::host
