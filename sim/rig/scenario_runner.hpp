#pragma once
// The rig's side of one cycle, shared by the in-process demo and the `tread rig` process: encode
// the scenario's inputs, take the node's answer frames, check every computed answer against the
// reference (the tyre model in double, the contact table in double, on the inputs as the node
// decoded them), advance the scenario and keep the trace.

#include <array>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "contact/rigid_contact.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "proto/rig_link.hpp"
#include "rig/rig_scenario.hpp"

namespace tread::host {

/// What the rig checks the node's answers against. Null members are not checked.
struct RigReference {
  const mf::MfParameters<double>* tyre{nullptr};
  mf::MfOptions options{};
  const contact::ContactTable* contact{nullptr};
};

struct AnswerCheck {
  std::uint64_t answers_checked{0};  ///< wheel and wheelset answers compared
  std::uint64_t stale_answers{0};    ///< answers flagged stale (zeros), not compared
  /// Answers flagged otherwise (input clamped to the table, output saturated, channel disabled):
  /// not compared either, so said.
  std::uint64_t flagged_answers{0};
  /// Cycles without this cycle's answer (none came in time, or the inputs reached the node after
  /// its deadline, so that its answer is of older inputs): not compared.
  std::uint64_t unchecked_cycles{0};
  /// The node's answers (NodeStatus and the frames after it) to no cycle the rig was waiting for:
  /// those arriving between cycles (late ones), and in sync mode those whose NodeStatus.Cycle names
  /// another rig cycle (the node's input-timeout computations). Decoded aside, not taken.
  std::uint64_t other_answers{0};
  double max_force_error_n{0.0};
  double max_moment_error_nm{0.0};
  double max_delta_r_error_mm{0.0};
  double max_force_n{0.0};  ///< largest |F| of the reference

  /// Totals over several runs: counts add up, maxima are kept.
  void add(const AnswerCheck& other);
};

class ScenarioRunner {
 public:
  /// `link` carries the E2E counters of the session: one link for every scenario of a run.
  /// `wheelset_forces`: how many of the wheelsets the node answers wheel-rail forces for.
  ScenarioRunner(RigScenario& scenario, proto::RigLink& link, proto::Layout layout,
                 std::uint8_t wheels, std::uint8_t wheelsets, const RigReference& reference,
                 std::uint8_t wheelset_forces = 0);

  /// The frames of the cycle at `t_s` (the cycle frame last).
  std::span<const proto::CanFrame> begin_cycle(double t_s, std::uint32_t rig_cycle);
  /// One frame from the node (others are ignored). True when it completed this cycle's answer:
  /// every output message the node sends for the configured channels has arrived since the last
  /// NodeStatus (which the node sends first) after begin_cycle(). A sync-mode node's NodeStatus
  /// names the rig cycle it answers: an answer to another (the node's input-timeout computation),
  /// and any frame between end_cycle() and the next begin_cycle(), is decoded aside (its E2E
  /// counters still count) and never taken as this cycle's.
  bool on_frame(const proto::CanFrame& frame);
  /// Checks the answers (when `answered`: this cycle's answer came, computed on this cycle's
  /// inputs; else the cycle is counted as unchecked), advances the scenario by `dt_s` with the
  /// last answers the rig has and appends the trace row.
  void end_cycle(double dt_s, bool answered = true);

  [[nodiscard]] bool done() const {
    return t_s_ >= scenario_.duration_s() - 1e-9 || scenario_.finished();
  }
  [[nodiscard]] double time_s() const { return t_s_; }
  [[nodiscard]] const AnswerCheck& check() const { return check_; }
  [[nodiscard]] const proto::RigLink& link() const { return link_; }
  [[nodiscard]] RigScenario& scenario() { return scenario_; }
  [[nodiscard]] std::uint64_t cycles() const { return cycles_; }

  /// Writes t_s and the scenario's columns.
  void write_trace(const std::filesystem::path& csv) const;

 private:
  RigScenario& scenario_;
  std::uint8_t wheels_;
  std::uint8_t wheelsets_;
  RigReference reference_;
  proto::RigLink& link_;
  proto::Layout layout_;
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames_{};
  std::size_t frame_count_{0};
  std::uint64_t expected_mask_{0};  ///< node output messages of a cycle (by message index)
  std::uint64_t received_mask_{0};
  std::uint32_t rig_cycle_{0};  ///< the cycle begin_cycle() sent
  bool cycle_open_{false};      ///< between begin_cycle() and end_cycle()
  bool other_answer_{true};  ///< the frames since the last NodeStatus are not this cycle's answer
  proto::RigData seen_{};
  proto::NodeData answers_{};
  proto::NodeData other_{};  ///< where another cycle's answer is decoded
  AnswerCheck check_{};
  double t_s_{0.0};
  std::uint64_t cycles_{0};
  std::vector<std::string> columns_;
  std::vector<double> trace_;  ///< rows of 1 + columns_.size() values
  std::vector<double> row_;
};

struct ScenarioOutcome {
  std::string name;
  std::string description;
  std::uint64_t cycles{0};
  AnswerCheck check;
  std::vector<ScenarioMetric> metrics;
  std::filesystem::path trace_csv;
  std::vector<std::filesystem::path> plots;
};

/// After the run: the outcome, the trace written to out_dir/<name>.csv and (if `plot`) the plots.
ScenarioOutcome finish_scenario(ScenarioRunner& runner, const std::filesystem::path& out_dir,
                                bool plot);
void print_scenario_outcome(std::ostream& out, const ScenarioOutcome& outcome);

}  // namespace tread::host
