#pragma once
// The HIL demo: a tread node and the rig on one CAN bus (the in-process stub bus by default, or a
// SocketCAN link), cycle by cycle on a real or simulated clock. The rig runs its scenarios one
// after the other (vehicle manoeuvres on the road wheels, hunting wheelsets on the rail channels)
// with the node's answers in the loop, checks every answer against the reference model evaluated in
// double on the same inputs, and writes a trace (CSV) and plots per scenario.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "node/node_session.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/scenario_runner.hpp"

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
  hal::RealtimeRequest realtime{};  ///< SCHED_FIFO / mlockall / CPU affinity for the loop
};

struct DemoResult {
  SessionReport report;
  std::uint64_t rig_frames_accepted{0};
  std::uint64_t rig_frames_rejected{0};
  std::uint64_t unanswered_cycles{0};  ///< no complete answer within 200 us (SocketCAN)
  std::vector<ScenarioOutcome> scenarios;
  AnswerCheck answers;  ///< over all scenarios
};

DemoResult run_demo(const DemoSettings& settings);
void print_demo(std::ostream& out, const DemoSettings& settings, const DemoResult& result);

}  // namespace tread::host
