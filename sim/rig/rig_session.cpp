#include "rig/rig_session.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "posix/posix_clock.hpp"
#include "rig/scenario_catalogue.hpp"
#include "runtime/node_runtime.hpp"
#include "runtime/protocol_socket.hpp"
#include "socketcan/socketcan_bus.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::host {

ScenarioContext rig_scenario_context(const RigSettings& s) {
  ScenarioContext context;
  context.tir = s.tir;
  context.wheels = s.wheels;
  context.wheelsets = s.wheelsets;
  context.wheelset_forces = s.wheelset_forces;
  context.friction = s.friction;
  context.mu = s.mu;
  context.wheelset_profile = s.wheelset_profile;
  context.wheelset_ymax_mm = s.wheelset_ymax_mm;
  context.wheelset_step_mm = s.wheelset_step_mm;
  context.sweep_duration_s = s.sweep_duration_s;
  context.period_s = static_cast<double>(s.period_us) * 1e-6;
  if (s.wheels > 0) context.tyre_options = node_tyre_options(s.use_mode, s.side);
  return context;
}

RigReport run_rig(const RigSettings& s) {
  const ScenarioContext context = rig_scenario_context(s);
  const std::vector<std::unique_ptr<RigScenario>> scenarios = make_scenarios(s.scenarios, context);
  mf::MfParameters<double> tyre{};
  contact::ContactTable contact_table;
  RigReference reference;
  if (s.wheels > 0) {
    tyre = tyre::load_mf_parameters(s.tir).params;
    reference.tyre = &tyre;
    reference.options = context.tyre_options;
  }
  if (s.wheelsets > 0) {
    contact_table = reference_contact_table(context);
    reference.contact = &contact_table;
  }

  // Only the node's outputs (and error frames) reach the rig: other traffic is dropped by the
  // kernel, as on the node's side.
  hal::SocketCanBus bus;
  open_protocol_socket(bus, s.can, s.layout, proto::Direction::node_to_rig,
                       "tread rig talks to a node process over SocketCAN only: run both in the VM "
                       "harness (scripts/vm/run-in-vm.sh), or node and rig in one process with "
                       "tread demo --can stub");
  RigReport r;
  r.receive_buffer_bytes = bus.receive_buffer_bytes();
  proto::RigLink link(s.layout, s.wheels, s.wheelsets, s.wheelset_forces);
  hal::PosixClock clock;
  const std::int64_t period_ns = (s.pace_us > 0 ? s.pace_us : s.period_us) * 1000;
  const auto timeout_ns = static_cast<std::int64_t>(s.answer_timeout_ms * 1e6);
  const double dt_s = static_cast<double>(s.period_us) * 1e-6;
  std::uint32_t rig_cycle = 0;
  std::int64_t deadline = clock.now_ns();
  proto::NodeData status_view{};
  // Sorts one received frame: error frames and foreign traffic are counted; node outputs go through
  // the runner (E2E check, decode). True when it completed the cycle's answer.
  const auto take = [&](ScenarioRunner& runner, const proto::CanFrame& f) {
    if (f.error) {
      ++r.error_frames;
      return false;
    }
    const proto::MessageSpec* m = proto::find_message(s.layout, f.id);
    if (f.extended || m == nullptr || m->direction != proto::Direction::node_to_rig) {
      ++r.foreign_frames;
      return false;
    }
    const std::uint64_t rejected_before = link.rejected();
    const std::uint64_t accepted_before = link.accepted();
    const bool complete = runner.on_frame(f);
    r.node_frames_rejected += link.rejected() - rejected_before;
    r.node_frames_accepted += link.accepted() - accepted_before;
    if (m->id == proto::kNodeStatusId && link.accepted() > accepted_before) {
      static_cast<void>(proto::decode(*m, f, status_view));
    }
    return complete;
  };
  // Runners are kept to the end: their outcomes (results, reference runs, traces, plots) are
  // worked out after the last cycle, so the node never waits for the rig between scenarios.
  std::vector<std::unique_ptr<ScenarioRunner>> runners;
  for (auto& scenario : scenarios) {
    runners.push_back(std::make_unique<ScenarioRunner>(*scenario, link, s.layout, s.wheels,
                                                       s.wheelsets, reference, s.wheelset_forces));
    ScenarioRunner& runner = *runners.back();
    while (!runner.done()) {
      // Anything that arrived between cycles is not this cycle's answer (e.g. the node's
      // input-timeout computation while the rig was held up): take it out of the way first.
      proto::CanFrame f{};
      while (bus.receive(f) == Status::ok) {
        static_cast<void>(take(runner, f));
        ++r.stray_frames;
      }
      for (const proto::CanFrame& out : runner.begin_cycle(runner.time_s(), rig_cycle++)) {
        if (bus.send(out) == Status::ok) {
          ++r.frames_sent;
        } else {
          ++r.send_refused;
        }
      }
      ++r.cycles;
      bool answered = false;
      const std::int64_t give_up = clock.now_ns() + timeout_ns;
      while (!answered && clock.now_ns() < give_up) {
        bool any = false;
        while (!answered && bus.receive(f) == Status::ok) {
          any = true;
          answered = take(runner, f);
        }
        if (!any) {
          static_cast<void>(clock.sleep_until_ns(clock.now_ns() + 20'000));
        }
      }
      r.late_cycles += answered ? 0U : 1U;
      runner.end_cycle(dt_s, answered);
      deadline += period_ns;
      const std::int64_t now = clock.now_ns();
      if (deadline > now) {
        static_cast<void>(clock.sleep_until_ns(deadline));
      } else {
        deadline = now;  // behind (slow node or machine): carry on from now, lockstep keeps order
      }
    }
  }
  for (auto& runner : runners) {
    ScenarioOutcome o = finish_scenario(*runner, s.out_dir, s.plot);
    r.answers.add(o.check);
    r.scenarios.push_back(std::move(o));
  }
  r.rx_queue_overflows = bus.rx_overflows();
  r.frames_saturated = link.saturated_frames();
  r.node_overruns = status_view.status.overruns;
  r.node_rejected = status_view.status.rejected;
  r.node_cycle = status_view.status.cycle;
  r.node_state = status_view.status.state;
  return r;
}

void print_rig_report(std::ostream& out, const RigReport& r) {
  out << "rig cycles           " << r.cycles << " (late answers " << r.late_cycles
      << ", frames between cycles " << r.stray_frames << ")\n";
  out << "rig frames sent      " << r.frames_sent << " (refused " << r.send_refused
      << "; with a value clamped to its signal's range " << r.frames_saturated << ")\n";
  out << "node frames          " << r.node_frames_accepted << " accepted, "
      << r.node_frames_rejected << " rejected\n";
  out << "other traffic        " << r.foreign_frames << " foreign frames, " << r.error_frames
      << " error frames\n";
  out << "rx queue overflow    " << r.rx_queue_overflows
      << " (frames the kernel dropped for the rig's full receive queue, SO_RXQ_OVFL; buffer "
      << r.receive_buffer_bytes << " bytes)\n";
  out << "answers checked      " << r.answers.answers_checked << " (stale "
      << r.answers.stale_answers << "; flagged clamped, saturated or disabled "
      << r.answers.flagged_answers << "; " << r.answers.other_answers
      << " answers of the node to no cycle the rig waited for, not taken)\n";
  out << "max |dF|             " << r.answers.max_force_error_n << " N, max |dMz| "
      << r.answers.max_moment_error_nm << " N m, max |d delta_r| " << r.answers.max_delta_r_error_mm
      << " mm (vs the reference in double; quantisation 0.5 N / 0.025 N m / 0.0005 mm)\n";
  out << "node status          cycle " << r.node_cycle
      << ((r.node_state & proto::kNodeSyncMode) != 0U ? " (sync mode: the last rig cycle answered)"
                                                      : "")
      << ", overruns " << r.node_overruns << ", rejected " << r.node_rejected << "\n";
  for (const ScenarioOutcome& o : r.scenarios) {
    print_scenario_outcome(out, o);
  }
}

}  // namespace tread::host
