// `tread demo`: the README's main job — node + rig scenarios on the in-process CAN bus (or --can
// vcan0), summary, trace and plots.
#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/node_options.hpp"
#include "rig/hil_demo.hpp"
#include "rig/scenario_catalogue.hpp"

namespace tread::cli {
namespace {

/// The demo's wheel/rail pair: EPS on 60E1 1:40, whose contact is smooth at the centre, so the
/// dynamic-hunting scenario's linearisation describes the motion (S1002 on 60E1 1:40 has a delta r
/// jump at y = 0).
constexpr const char* kDemoWheelsetProfile = "wheel=EPS,rail=60E1,cant=1:40";

void add_demo_command(CLI::App& app) {
  auto* demo =
      app.add_subcommand("demo", "Run the HIL demo: node + rig (in-process bus by default)");
  static NodeCliState state;
  static host::DemoSettings settings;
  static std::string clock = "posix";
  state.wheelsets = 2;
  state.wheelset_forces = 1;
  state.settings.wheelset_profile = kDemoWheelsetProfile;
  add_node_options(*demo, state, false);
  demo->get_option("--wheelsets")->default_val(2);
  demo->get_option("--wheelset-forces")->default_val(1);
  demo->get_option("--wheelset-profile")->default_val(kDemoWheelsetProfile);
  demo->add_option("--can", settings.can,
                   "stub (in-process bus) or a SocketCAN interface such as vcan0")
      ->capture_default_str();
  demo->add_option("--clock", clock, "posix (real time) or sim (as fast as possible)")
      ->check(CLI::IsMember({"posix", "sim"}))
      ->capture_default_str();
  demo->add_option(
          "--scenario", settings.scenarios,
          "scenarios to run, in order (default: braking, step-steer, sine-dwell with 4 "
          "wheels; hunting with wheelsets; dynamic-hunting with wheelset forces): braking, "
          "step-steer, sine-dwell, hunting, dynamic-hunting, curving, sweep. dynamic-hunting and "
          "curving turn on the node's wheel-rail forces for wheelset 0")
      ->delimiter(',');
  demo->add_option("--sweep-duration-s", settings.sweep_duration_s,
                   "length of the 'sweep' scenario (tyre test machine sweeps)")
      ->check(host::finite_within(0.001, 3600.0, "the sweep's length in s"))
      ->capture_default_str();
  demo->add_option("--period-us", settings.period_us,
                   "cycle period (at most 5000 us but for 'sweep': the scenarios integrate the "
                   "vehicle at it)")
      ->check(CLI::Range(50, 1'000'000))
      ->capture_default_str();
  demo->add_option("--out", settings.out_dir, "directory for the trace and plots")
      ->capture_default_str();
  demo->add_option(
          "--rt-priority", settings.realtime.fifo_priority,
          "SCHED_FIFO priority 1..99 (0: leave); with it, /dev/cpu_dma_latency is held at 0 "
          "(no deep idle states, as cyclictest does)")
      ->check(CLI::Range(0, 99));
  demo->add_flag("--mlock", settings.realtime.lock_memory, "lock all memory (mlockall)");
  demo->add_option("--cpu", settings.realtime.cpu, "pin the node's thread to this CPU");
  demo->add_option("--rig-cpu", settings.rig_cpu,
                   "pin the rig's thread to this CPU (default: another CPU than --cpu's, if set)");
  demo->add_option("--rig-priority", settings.rig_priority,
                   "SCHED_FIFO priority of the rig's thread (default: --rt-priority minus 10, at "
                   "least 1; 0: the default scheduler)")
      ->check(CLI::Range(0, 99));
  demo->add_flag(
      "--no-plot", [](std::int64_t) { settings.plot = false; }, "write the trace but no plot");
  demo->add_option("--log", settings.log,
                   "candump log of the node's traffic (replay with tread node --replay)");
  demo->callback([] {
    check_scenario_period(settings.scenarios, static_cast<int>(settings.period_us));
    // The dynamic-hunting and curving scenarios run on the node's wheel-rail forces.
    const bool forces =
        std::any_of(settings.scenarios.begin(), settings.scenarios.end(),
                    [](const std::string& n) { return host::needs_wheelset_forces(n); });
    if (forces) {
      state.wheelsets = std::max(state.wheelsets, 1);
      state.wheelset_forces = std::max(state.wheelset_forces, 1);
    }
    settings.node = node_settings(state);
    settings.sim_clock = clock == "sim";
    const auto& rt = settings.realtime;
    if (settings.sim_clock && (rt.fifo_priority > 0 || rt.lock_memory || rt.cpu >= 0 ||
                               settings.rig_cpu >= 0 || settings.rig_priority >= 0)) {
      std::cerr << "tread demo: warning: --rt-priority, --mlock, --cpu, --rig-cpu and "
                   "--rig-priority apply to --clock posix: ignored on the simulated clock\n";
    }
    const host::DemoResult result = host::run_demo(settings);
    host::print_demo(std::cout, settings, result);
    if (!result.report.log_error.empty()) {
      throw std::runtime_error(result.report.log_error);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("demo", add_demo_command);

}  // namespace tread::cli
