#pragma once
// `tread rig`: the rig side as its own process, talking to a tread node only through CAN frames.
// It runs the same scenarios as `tread demo` in lockstep with the node: each cycle it sends the
// inputs (the cycle frame last), waits for the node's answer (NodeStatus first, then every output
// message of the configured channels), checks every answer against the reference model, advances
// the scenario, and sleeps to the next period. Kernel ID filters pass only the node's output IDs
// and error frames. With the node in sync mode (`tread node --mode sync`, its --timeout-ms longer
// than the rig's pace, so that it never computes on its own between the rig's cycles) the trace is
// the same, value for value, as the in-process run's (`tread demo --clock sim`), whatever the
// timing of the two processes. Other traffic (floods, error frames, malformed frames) is counted
// and ignored.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "proto/messages.hpp"
#include "rig/scenario_catalogue.hpp"
#include "rig/scenario_runner.hpp"

namespace tread::host {

struct RigSettings {
  std::string can{"vcan0"};
  proto::Layout layout{proto::Layout::classic};
  std::uint8_t wheels{4};
  std::uint8_t wheelsets{0};
  std::uint8_t wheelset_forces{0};  ///< the node's --wheelset-forces
  std::string friction{"kalker"};   ///< the node's --friction and --mu (the reference)
  double mu{0.0};
  std::filesystem::path tir;  ///< the node's tyre file (the reference)
  int use_mode{111};          ///< the node's --use-mode and --side (the reference's options)
  std::string side{"as-measured"};
  std::string wheelset_profile;   ///< the node's wheelset profile (the reference)
  double wheelset_ymax_mm{12.0};  ///< the node's contact table range and step
  double wheelset_step_mm{0.1};
  std::vector<std::string> scenarios;  ///< empty: the defaults for the channels
  double sweep_duration_s{4.0};
  std::int64_t period_us{1000};  ///< the simulated step (the node's period)
  /// Wall-clock time per cycle; 0: the period (real time). Longer paces a lockstep run slower than
  /// real time (same trace: the simulated step stays period_us).
  std::int64_t pace_us{0};
  double answer_timeout_ms{100.0};  ///< wait for the node's answer of a cycle at most this long
  std::filesystem::path out_dir{"tread-rig"};
  bool plot{false};
};

struct RigReport {
  std::uint64_t cycles{0};
  std::uint64_t frames_sent{0};
  std::uint64_t send_refused{0};
  std::uint64_t frames_saturated{0};  ///< input frames sent with a signal clamped to its range
  std::uint64_t node_frames_accepted{0};
  std::uint64_t node_frames_rejected{0};
  /// Frames that are not node outputs (the kernel filter passes only the node's IDs, so these are
  /// standard frames on them that fail to be a node output, e.g. a flood's).
  std::uint64_t foreign_frames{0};
  std::uint64_t error_frames{0};
  /// Frames the kernel dropped because the rig's receive queue was full (SO_RXQ_OVFL), and the
  /// receive buffer it granted.
  std::uint64_t rx_queue_overflows{0};
  int receive_buffer_bytes{0};
  std::uint64_t late_cycles{0};    ///< cycles whose answer did not come within the timeout
  std::uint64_t stray_frames{0};   ///< frames that arrived between cycles (not an answer)
  AnswerCheck answers;             ///< over all scenarios
  std::uint32_t node_overruns{0};  ///< from the last NodeStatus
  std::uint32_t node_rejected{0};
  std::uint32_t node_cycle{0};
  std::uint8_t node_state{0};  ///< NodeStatus.State of the last status
  std::vector<ScenarioOutcome> scenarios;
};

/// The scenarios' and the answer check's set-up from the node's options as the rig was given them
/// (tyre file, useMode and mounted side, wheelsets, contact, friction). Throws on a bad value.
ScenarioContext rig_scenario_context(const RigSettings& settings);

/// Runs the scenarios over SocketCAN. Throws std::runtime_error when the link cannot be used.
RigReport run_rig(const RigSettings& settings);
void print_rig_report(std::ostream& out, const RigReport& report);

}  // namespace tread::host
