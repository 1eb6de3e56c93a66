#include "rig/hil_demo.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <stdexcept>

#include "loop/loop_runner.hpp"
#include "rig/demo_rig.hpp"
#include "rig/demo_threads.hpp"
#include "runtime/candump_log.hpp"
#include "stub/sim_clock.hpp"
#include "stub/stub_can_bus.hpp"

namespace tread::host {
namespace {

/// The simulated clock: node and rig in one thread, cycle by cycle, on the in-process stub bus.
DemoResult co_simulate(const DemoSettings& s, NodeRuntime& runtime) {
  hal::SimClock clock(0);
  hal::StubCanNetwork net(&hal::clock_now<hal::SimClock>, &clock);
  hal::StubCanEndpoint& node_bus = net.endpoint(0);
  hal::StubCanEndpoint& rig_bus = net.endpoint(1);
  DemoRig rig(s, runtime);
  CandumpWriter writer;
  CandumpRecorder recorder;
  if (!s.log.empty()) {
    writer.open(s.log, s.can);
    recorder.writer = &writer;
  }
  hal::NoPin pin;
  hal::LoopConfig loop_config;
  loop_config.period_ns = s.period_us * 1000;
  return runtime.visit([&](auto& node) {
    hal::LoopRunner loop(node, node_bus, clock, pin, loop_config, recorder);
    DemoResult result;
    std::uint32_t rig_cycle = 0;
    for (auto& runner : rig.runners()) {
      while (!runner->done()) {
        for (const proto::CanFrame& f : runner->begin_cycle(runner->time_s(), rig_cycle++)) {
          static_cast<void>(rig_bus.send(f));
        }
        loop.run_periodic_cycle();
        bool answered = false;
        proto::CanFrame f{};
        while (rig_bus.receive(f) == Status::ok) {
          answered = runner->on_frame(f) || answered;
        }
        result.unanswered_cycles += answered ? 0U : 1U;
        runner->end_cycle(rig.step_s(), answered);
      }
    }
    // Outcomes (results, reference runs, traces, plots) after the last cycle, as `tread rig` does.
    rig.finish(s, result);
    result.report.loop = loop.stats();
    result.report.counters = runtime.counters();
    result.report.log_error = writer.finish();
    return result;
  });
}

}  // namespace

DemoResult run_demo(const DemoSettings& s) {
  if (s.sim_clock && s.can != "stub") {
    throw std::runtime_error("--clock sim needs the in-process bus (--can stub)");
  }
  NodeRuntime runtime(s.node);
  DemoResult result = s.sim_clock ? co_simulate(s, runtime) : run_demo_threads(s, runtime);
  result.report.notes +=
      runtime.tir_warning().empty() ? "" : "note: " + runtime.tir_warning() + "\n";
  return result;
}

void print_demo(std::ostream& out, const DemoSettings& s, const DemoResult& r) {
  out << "tread HIL demo — node + rig on " << (s.can == "stub" ? "the in-process CAN bus" : s.can)
      << " (" << (s.node.node.layout == proto::Layout::fd ? "CAN FD" : "classic CAN") << " layout, "
      << (s.sim_clock ? "simulated" : "real") << " clock, period " << s.period_us << " us)\n";
  const char* arithmetic = s.node.fixed ? "fixed point" : "float";
  if (s.node.node.wheels > 0) {
    out << "tyre model        " << s.node.tir.string() << " (" << arithmetic
        << " on the node, double reference)\n";
  }
  if (s.node.node.wheelsets > 0) {
    out << "wheelsets         " << static_cast<int>(s.node.node.wheelsets) << ": "
        << s.node.wheelset_profile << "\n";
  }
  out << "\n";
  print_report(out, r.report, !s.sim_clock);
  if (r.rig_frames_saturated > 0) {
    out << "warning           " << r.rig_frames_saturated
        << " input frames carried a value beyond its signal's range, sent clamped (e.g. a slip "
           "angle beyond 0.655 rad): the node answered the clamped value, the trace holds the "
           "scenario's own\n";
  }
  out << "rig frames        " << r.rig_frames_accepted << " accepted, " << r.rig_frames_rejected
      << " rejected; cycles without a complete answer " << r.unanswered_cycles << "\n";
  if (r.threaded) {
    const hal::LatencyHistogram& h = r.answer_latency;
    const bool sync = s.node.node.schedule == node::Schedule::sync;
    out << (sync ? "CAN-in -> CAN-out" : "deadline -> answer") << " p50 "
        << percentile_text(h, 0.50) << " us, p99 " << percentile_text(h, 0.99) << " us, max "
        << std::fixed << std::setprecision(1) << static_cast<double>(h.max_ns()) / 1000.0 << " us ("
        << h.count() << " answers; "
        << (sync ? "the rig's cycle frame to the node's last answer frame"
                 : "the node's deadline to its last answer frame")
        << ")\n";
    out.unsetf(std::ios::floatfield);
    if (!sync) {
      out << "late inputs       " << r.late_sends
          << " cycles whose inputs the rig sent after the node's deadline (not checked)\n";
    }
    out << "stray answers     " << r.stray_answers
        << " (outside a cycle's window, or begun before its inputs reached the node)\n";
    if (!s.log.empty()) {
      out << "log ring          " << r.log_records_dropped << " records dropped\n";
    }
    out << r.rig_notes;
  }
  out << std::setprecision(4);
  out << "answers vs the reference (double, on the inputs the node decoded): "
      << r.answers.answers_checked << " checked, " << r.answers.stale_answers << " stale, "
      << r.answers.flagged_answers << " flagged clamped, saturated or disabled (not checked)\n";
  if (s.node.node.wheels > 0) {
    out << "  max |dF|          " << r.answers.max_force_error_n << " N  ("
        << 100.0 * r.answers.max_force_error_n / std::max(r.answers.max_force_n, 1.0)
        << " % of the largest force " << r.answers.max_force_n << " N; quantisation 0.5 N + "
        << arithmetic << ")\n";
    out << "  max |dMz|         " << r.answers.max_moment_error_nm << " N m\n";
  }
  if (s.node.node.wheelsets > 0) {
    out << "  max |d delta_r|   " << r.answers.max_delta_r_error_mm
        << " mm (quantisation 0.0005 mm + " << (s.node.fixed ? "integer" : "float") << " table)\n";
  }
  for (const ScenarioOutcome& o : r.scenarios) {
    print_scenario_outcome(out, o);
  }
}

}  // namespace tread::host
