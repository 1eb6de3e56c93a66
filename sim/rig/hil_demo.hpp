#pragma once
// The HIL demo: a tread node and the rig on one CAN bus (in-process by default, or a SocketCAN
// link). On the simulated clock the two run cycle by cycle in one thread (as fast as possible, the
// same trace every time). On the real clock the node runs as it would on a rig: on its own thread
// (its own CPU, SCHED_FIFO, locked memory, no I/O: its log goes through a lock-free ring to a
// writer thread), the rig on another thread at a lower priority, the two joined by a lock-free
// in-process link or the SocketCAN interface; the rig measures the node's answer latency. The rig
// runs its scenarios one after the other (vehicle manoeuvres on the road wheels, hunting wheelsets
// on the rail channels) with the node's answers in the loop, checks every answer against the
// reference model evaluated in double on the same inputs, and writes a trace (CSV) and plots per
// scenario.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "loop/latency_histogram.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/scenario_runner.hpp"
#include "runtime/node_session.hpp"

namespace tread::host {

struct DemoSettings {
  NodeSettings node;
  std::string can{"stub"};
  bool sim_clock{false};
  std::vector<std::string> scenarios;  ///< empty: the defaults for the channels
  double sweep_duration_s{4.0};        ///< length of the "sweep" scenario
  std::int64_t period_us{1000};
  std::filesystem::path out_dir{"tread-demo"};
  std::filesystem::path log;        ///< candump log of the node's traffic (replayable)
  bool plot{true};                  ///< draw the plots with gnuplot
  hal::RealtimeRequest realtime{};  ///< SCHED_FIFO / mlockall / CPU affinity for the node's thread
  /// Real clock: the rig's thread. CPU -1: another CPU than the node's when the node is pinned (and
  /// there is one), else unpinned. Priority -1: 10 below the node's SCHED_FIFO priority (at least
  /// 1) when the node has one, else the default scheduler; 0: the default scheduler.
  int rig_cpu{-1};
  int rig_priority{-1};
};

struct DemoResult {
  SessionReport report;
  std::uint64_t rig_frames_accepted{0};
  std::uint64_t rig_frames_rejected{0};
  std::uint64_t rig_frames_saturated{0};  ///< input frames sent with a signal clamped to its range
  std::uint64_t unanswered_cycles{0};     ///< real clock: no complete answer in the cycle's window
  /// Real clock (the node on its own thread, the rig on another), as the rig measured them:
  /// sync mode: CAN-in → CAN-out, from the rig's cycle frame (the send) to the node's last answer
  /// frame of the cycle (its timestamp: the kernel's receive time on SocketCAN, the send time on
  /// the in-process link); periodic mode: from the node's deadline to that frame.
  hal::LatencyHistogram answer_latency;
  /// Periodic mode: cycles whose inputs the rig finished sending after the node's deadline (the
  /// node answered older inputs: not checked).
  std::uint64_t late_sends{0};
  /// Answers (counted by their NodeStatus) that were not a cycle's: came between the windows, or
  /// began before the cycle's inputs reached the node (a late answer of an earlier cycle).
  std::uint64_t stray_answers{0};
  std::uint64_t log_records_dropped{0};  ///< --log: records the full log ring refused
  bool threaded{false};                  ///< the node ran on its own thread (real clock)
  std::string rig_notes;                 ///< the rig thread's real-time set-up
  std::vector<ScenarioOutcome> scenarios;
  AnswerCheck answers;  ///< over all scenarios
};

DemoResult run_demo(const DemoSettings& settings);
void print_demo(std::ostream& out, const DemoSettings& settings, const DemoResult& result);

}  // namespace tread::host
