#include "rig/hil_demo.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <stdexcept>

#include "loop/loop_runner.hpp"
#include "node/candump_log.hpp"
#include "node/protocol_socket.hpp"
#include "posix/posix_clock.hpp"
#include "rig/scenario_catalogue.hpp"
#include "socketcan/socketcan_bus.hpp"
#include "stub/sim_clock.hpp"
#include "stub/stub_can_bus.hpp"

namespace tread::host {
namespace {

ScenarioContext context_of(const DemoSettings& s) {
  ScenarioContext c;
  c.tir = s.node.tir;
  c.wheels = s.node.node.wheels;
  c.wheelsets = s.node.node.wheelsets;
  c.wheelset_forces = s.node.node.wheelset_forces;
  c.friction = s.node.friction;
  c.mu = s.node.mu;
  c.materials = s.node.materials;
  c.wheelset_profile = s.node.wheelset_profile;
  c.wheelset_ymax_mm = s.node.wheelset_ymax_mm;
  c.wheelset_step_mm = s.node.wheelset_step_mm;
  c.sweep_duration_s = s.sweep_duration_s;
  c.period_s = static_cast<double>(s.period_us) * 1e-6;
  return c;
}

template <typename ClockT, typename NodeBus, typename RigBus>
DemoResult co_simulate(const DemoSettings& s, NodeRuntime& runtime, ClockT& clock,
                       NodeBus& node_bus, RigBus& rig_bus) {
  const node::NodeConfig& cfg = runtime.config();
  const ScenarioContext context = context_of(s);
  const std::vector<std::unique_ptr<RigScenario>> scenarios = make_scenarios(s.scenarios, context);
  contact::ContactTable contact_reference;
  RigReference reference;
  if (cfg.wheels > 0) {
    reference.tyre = &runtime.tyre_parameters();
    reference.options = runtime.tyre_options();
  }
  if (cfg.wheelsets > 0) {
    contact_reference = reference_contact_table(context);
    reference.contact = &contact_reference;
  }

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
    proto::RigLink link(cfg.layout, cfg.wheels, cfg.wheelsets, cfg.wheelset_forces);
    const double dt_s = static_cast<double>(s.period_us) * 1e-6;
    std::filesystem::create_directories(s.out_dir);

    DemoResult result;
    std::uint32_t rig_cycle = 0;
    // Outcomes (results, reference runs, traces, plots) after the last cycle, as `tread rig` does.
    std::vector<std::unique_ptr<ScenarioRunner>> runners;
    for (auto& scenario : scenarios) {
      runners.push_back(std::make_unique<ScenarioRunner>(
          *scenario, link, cfg.layout, cfg.wheels, cfg.wheelsets, reference, cfg.wheelset_forces));
      ScenarioRunner& runner = *runners.back();
      while (!runner.done()) {
        for (const proto::CanFrame& f : runner.begin_cycle(runner.time_s(), rig_cycle++)) {
          static_cast<void>(rig_bus.send(f));
        }
        loop.run_periodic_cycle();
        // The node's answer of this cycle (SocketCAN delivers within microseconds; poll briefly).
        bool answered = false;
        const std::int64_t give_up = clock.now_ns() + 200'000;
        proto::CanFrame f{};
        do {
          while (rig_bus.receive(f) == Status::ok) {
            answered = runner.on_frame(f) || answered;
          }
        } while (!answered && clock.now_ns() < give_up && !std::is_same_v<ClockT, hal::SimClock>);
        result.unanswered_cycles += answered ? 0U : 1U;
        runner.end_cycle(dt_s);
      }
    }
    for (auto& runner : runners) {
      ScenarioOutcome o = finish_scenario(*runner, s.out_dir, s.plot);
      result.answers.add(o.check);
      result.scenarios.push_back(std::move(o));
    }
    result.report.loop = loop.stats();
    result.report.counters = runtime.counters();
    result.rig_frames_accepted = link.accepted();
    result.rig_frames_rejected = link.rejected();
    result.report.log_error = writer.finish();
    return result;
  });
}

}  // namespace

DemoResult run_demo(const DemoSettings& s) {
  NodeRuntime runtime(s.node);
  const hal::RealtimeReport rt = hal::apply_realtime(s.realtime);
  std::cerr << rt.messages << std::flush;  // at once, and again in the summary
  DemoResult result;
  if (s.can == "stub") {
    if (s.sim_clock) {
      hal::SimClock clock(0);
      hal::StubCanNetwork net(&hal::clock_now<hal::SimClock>, &clock);
      result = co_simulate(s, runtime, clock, net.endpoint(0), net.endpoint(1));
    } else {
      hal::PosixClock clock;
      hal::StubCanNetwork net(&hal::clock_now<hal::PosixClock>, &clock);
      result = co_simulate(s, runtime, clock, net.endpoint(0), net.endpoint(1));
    }
  } else {
    if (s.sim_clock) {
      throw std::runtime_error("--clock sim needs the in-process bus (--can stub)");
    }
    // Each end set up as `tread node` and `tread rig` set theirs up: only its incoming messages.
    hal::SocketCanBus node_bus;
    hal::SocketCanBus rig_bus;
    open_protocol_socket(node_bus, s.can, s.node.node.layout, proto::Direction::rig_to_node);
    open_protocol_socket(rig_bus, s.can, s.node.node.layout, proto::Direction::node_to_rig);
    hal::PosixClock clock;
    result = co_simulate(s, runtime, clock, node_bus, rig_bus);
  }
  result.report.notes =
      rt.messages + (runtime.tir_warning().empty() ? "" : "note: " + runtime.tir_warning() + "\n");
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
  out << "rig frames        " << r.rig_frames_accepted << " accepted, " << r.rig_frames_rejected
      << " rejected; cycles without a complete answer " << r.unanswered_cycles << "\n";
  out << std::setprecision(4);
  out << "answers vs the reference (double, on the inputs the node decoded):\n";
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
