#pragma once
// The HIL demo: a tread node and a scripted rig on one CAN bus (the in-process stub bus by default,
// or a SocketCAN link), cycle by cycle on a real or simulated clock. The rig compares every force
// the node sends with the reference model evaluated in double on the same inputs, and the demo
// writes a trace (CSV) and plots.

#include <filesystem>
#include <iosfwd>
#include <string>

#include "node/node_session.hpp"

namespace tread::host {

struct DemoSettings {
  NodeSettings node;
  std::string can{"stub"};
  bool sim_clock{false};
  double duration_s{4.0};
  std::int64_t period_us{1000};
  std::filesystem::path out_dir{"tread-demo"};
  std::filesystem::path log;        ///< candump log of the node's traffic (replayable)
  bool plot{true};                  ///< draw demo.png with gnuplot
  hal::RealtimeRequest realtime{};  ///< SCHED_FIFO / mlockall / CPU affinity for the loop
};

struct DemoResult {
  SessionReport report;
  std::uint64_t rig_frames_accepted{0};
  std::uint64_t rig_frames_rejected{0};
  double max_force_error_n{0.0};  ///< |F over CAN − F reference| over all wheels and cycles
  double max_force_n{0.0};        ///< largest |F| seen
  double max_moment_error_nm{0.0};
  double max_delta_r_error_mm{0.0};
  double peak_fx_n{0.0};
  double peak_fy_n{0.0};
  std::filesystem::path trace_csv;
  std::filesystem::path plot_png;
};

DemoResult run_demo(const DemoSettings& settings);
void print_demo(std::ostream& out, const DemoSettings& settings, const DemoResult& result);

}  // namespace tread::host
