// `tread node`: the real-time node on SocketCAN or the in-process bus, or a replay of its log.
#include <atomic>
#include <csignal>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/node_options.hpp"
#include "runtime/node_session.hpp"

namespace tread::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int /*signal*/) {
  g_stop.store(true);
}

void add_node_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "node", "Run the real-time node (SocketCAN or in-process bus), or replay a log");
  static NodeCliState state;
  static host::LiveOptions live;
  static std::string replay;
  static std::string clock = "posix";
  static std::string tx_log;
  static double duration_s = 0.0;
  add_node_options(*cmd, state, true);
  cmd->add_flag("--relaxation", state.settings.relaxation,
                "lag the received slips with the tyre's relaxation lengths (first-order transient; "
                "not for a rig that sends transient slips itself, as tread demo's and tread rig's "
                "vehicle does)");
  cmd->add_option("--can", live.can, "stub (in-process bus) or a SocketCAN interface such as vcan0")
      ->capture_default_str();
  cmd->add_option("--period-us", live.period_us, "cycle period")
      ->check(CLI::Range(50, 1'000'000))
      ->capture_default_str();
  cmd->add_option("--cycles", live.cycles,
                  "stop after this many cycles (0: run until SIGINT/SIGTERM)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (!text.empty() && text.size() < 20 &&
                text.find_first_not_of("0123456789") == std::string::npos) {
              return {};
            }
            return "'" + text + "': the cycle count is a whole number from 0";
          },
          "", "CYCLES"));
  cmd->add_option("--duration-s", duration_s,
                  "stop after this time (overrides --cycles; at least one period, at most 1e7 s)")
      ->check(host::finite_within(1e-6, 1e7, "the duration in s"));
  cmd->add_option("--gpio-chip", live.gpio_chip,
                  "libgpiod chip for the cycle pin (e.g. gpiochip0)");
  cmd->add_option("--gpio-cycle-line", live.gpio_cycle_line, "line offset of the cycle pin");
  cmd->add_option(
         "--rt-priority", live.realtime.fifo_priority,
         "SCHED_FIFO priority 1..99 (0: leave); with it, /dev/cpu_dma_latency is held at 0 "
         "(no deep idle states, as cyclictest does)")
      ->check(CLI::Range(0, 99));
  cmd->add_flag("--mlock", live.realtime.lock_memory, "lock all memory (mlockall)");
  cmd->add_option("--cpu", live.realtime.cpu, "pin the loop to this CPU");
  cmd->add_option("--log", live.log,
                  "candump log of every frame received and computed (refused sends too): "
                  "replayable");
  cmd->add_option("--replay", replay,
                  "replay a candump log written by --log instead of running live");
  cmd->add_option("--clock", clock, "posix (live) or sim (replay)")
      ->check(CLI::IsMember({"posix", "sim"}))
      ->capture_default_str();
  cmd->add_option("--tx-log", tx_log, "replay: write the replayed transmitted frames here");
  cmd->callback([] {
    const host::NodeSettings settings = node_settings(state);
    if (!replay.empty()) {
      if (clock != "sim") {
        throw CLI::ValidationError("--replay",
                                   "a replay runs on the simulated clock: add --clock sim");
      }
      const host::ReplayResult r = host::run_replay(settings, replay, live.period_us, tx_log);
      host::print_report(std::cout, r.report, false);
      std::cout << "replay            " << r.input_frames << " input frames, " << r.tx_frames
                << " frames transmitted; the log holds " << r.logged_tx_frames << "\n";
      if (!r.report.log_error.empty()) {
        throw std::runtime_error(r.report.log_error);
      }
      if (r.logged_tx_frames == 0) {
        std::cout << "replay            the log holds no transmitted frames to compare with\n";
        return;
      }
      if (!r.identical) {
        throw std::runtime_error("replay differs from the log: " + r.first_difference);
      }
      std::cout << "replay            transmitted stream identical to the log, bit for bit\n";
      return;
    }
    if (clock == "sim") {
      throw CLI::ValidationError("--clock", "the simulated clock is for --replay");
    }
    if (duration_s > 0.0) {
      live.cycles =
          static_cast<std::uint64_t>(duration_s * 1e6 / static_cast<double>(live.period_us));
      if (live.cycles == 0) {  // 0 cycles would mean "until stopped"
        throw CLI::ValidationError("--duration-s",
                                   std::to_string(duration_s) + " s is shorter than one period");
      }
    }
    if (!tx_log.empty()) {
      throw CLI::ValidationError("--tx-log", "writes the frames of a --replay: give --replay");
    }
    if (live.gpio_cycle_line >= 0 && live.gpio_chip.empty()) {
      throw CLI::ValidationError("--gpio-cycle-line", "needs --gpio-chip");
    }
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    const host::SessionReport report = host::run_live(settings, live, &g_stop);
    host::print_report(std::cout, report, true);
    if (!report.log_error.empty()) {
      throw std::runtime_error(report.log_error);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("node", add_node_command);

}  // namespace tread::cli
