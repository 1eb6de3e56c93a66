#pragma once
// Command-line options shared by `tread node` and `tread demo` (header-only: CLI11 is linked only
// into the tread executable).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/option_checks.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::cli {

#ifndef TREAD_DATA_DIR
#define TREAD_DATA_DIR "data"  // the project's data/ folder; CMake compiles in its absolute path
#endif

struct NodeCliState {
  host::NodeSettings settings;
  bool fd{false};
  std::string mode{"periodic"};
  int wheels{4};
  int wheelsets{0};
  int wheelset_forces{0};
  double timeout_ms{10.0};
  /// The --wheelset-forces option: a count given by the user above --wheelsets is an error, the
  /// command's default (the demo's 1) follows --wheelsets down.
  CLI::Option* wheelset_forces_option{nullptr};
};

/// The longest cycle period the rig's and demo's scenarios take: they integrate the vehicle,
/// wheelsets and wheel spin at the node's period, and above 5 ms the wheel dynamics are not
/// resolved (braking deceleration 30 % off at 10 ms, NaN at 20 ms).
inline constexpr int kScenarioPeriodMaxUs = 5000;

/// Throws if `period_us` is above kScenarioPeriodMaxUs and a scenario other than 'sweep' (tyre
/// test-machine sweeps: no dynamics) is to run; none given: the default ones, which integrate.
inline void check_scenario_period(const std::vector<std::string>& scenarios, int period_us) {
  if (period_us <= kScenarioPeriodMaxUs) return;
  const bool integrates =
      scenarios.empty() || std::any_of(scenarios.begin(), scenarios.end(),
                                       [](const std::string& n) { return n != "sweep"; });
  if (integrates) {
    throw CLI::ValidationError(
        "--period-us", std::to_string(period_us) +
                           " us: the scenarios integrate the vehicle, wheelsets and wheel spin at "
                           "the cycle period and need one of at most " +
                           std::to_string(kScenarioPeriodMaxUs) +
                           " us (braking is 30 % off at 10 000 us); only 'sweep' takes longer");
  }
}

inline void add_node_options(CLI::App& cmd, NodeCliState& s, bool tir_required) {
  auto* tir =
      cmd.add_option("--tir", s.settings.tir, "tyre property file (.tir) for the road wheels");
  if (tir_required) {
    tir->required();
  } else {
    s.settings.tir = std::string(TREAD_DATA_DIR) + "/tyres/MagicFormula61_Parameters.tir";
    tir->capture_default_str();
  }
  cmd.add_flag("--fd", s.fd, "CAN FD layout (fewer, larger frames) instead of classic CAN");
  cmd.add_option("--wheels", s.wheels, "road wheels (0..4)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  cmd.add_option("--wheelsets", s.wheelsets, "rail wheelsets (0..2)")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  cmd.add_option("--wheelset-profile", s.settings.wheelset_profile,
                 "wheel/rail pair for the contact table: key=value list with wheel|wheel-file, "
                 "rail|rail-file, rail-frame, cant, gauge, b2b, r0, r0-right "
                 "(e.g. wheel=S1002,rail=60E1,cant=1:40)");
  s.wheelset_forces_option =
      cmd.add_option(
             "--wheelset-forces", s.wheelset_forces,
             "of the wheelsets, how many also serve the wheel-rail forces (Hertz, Polach creep "
             "forces, Y/Q, Nadal margin; needs WheelsetMotion and WheelsetLoad from the rig)")
          ->check(CLI::Range(0, 2))
          ->capture_default_str();
  cmd.add_option("--friction", s.settings.friction,
                 "Polach parameters for the wheel-rail forces: kalker, dry or wet")
      ->check(CLI::IsMember({"kalker", "dry", "wet"}))
      ->capture_default_str();
  cmd.add_option("--mu", s.settings.mu,
                 "wheel-rail friction coefficient mu0, 0.01 to 1 (default: the set's)")
      ->check(host::finite_within(0.01, 1.0, "mu0"));
  cmd.add_option("--mode", s.mode,
                 "periodic (own schedule) or sync (compute on the rig's cycle frame)")
      ->check(CLI::IsMember({"periodic", "sync"}))
      ->capture_default_str();
  cmd.add_option("--timeout-ms", s.timeout_ms, "input timeout per channel (0.01 to 60000 ms)")
      ->check(host::finite_within(0.01, 60000.0, "the input timeout in ms"))
      ->capture_default_str();
  cmd.add_option("--use-mode", s.settings.use_mode, "MFeval useMode of the tyre model")
      ->capture_default_str();
  cmd.add_option("--side", s.settings.side, "mounted side: as-measured, left or right")
      ->check(CLI::IsMember({"as-measured", "left", "right"}))
      ->capture_default_str();
  cmd.add_flag("--fixed", s.settings.fixed,
               "run the node in fixed point, exactly as the FPU-less firmware image does (Q31.32 "
               "Magic Formula, the contact table in integers, integer signal scaling)");
}

/// Turns the parsed options into NodeSettings (call from the command's callback).
inline host::NodeSettings node_settings(NodeCliState& s) {
  if (s.wheelset_forces > s.wheelsets) {
    if (s.wheelset_forces_option == nullptr || s.wheelset_forces_option->count() == 0) {
      s.wheelset_forces = s.wheelsets;  // a default, not the user's count
    } else {
      throw CLI::ValidationError("--wheelset-forces",
                                 std::to_string(s.wheelset_forces) +
                                     " wheelsets with forces, but --wheelsets " +
                                     std::to_string(s.wheelsets));
    }
  }
  host::NodeSettings out = s.settings;
  out.node.layout = s.fd ? proto::Layout::fd : proto::Layout::classic;
  out.node.wheels = static_cast<std::uint8_t>(s.wheels);
  out.node.wheelsets = static_cast<std::uint8_t>(s.wheelsets);
  out.node.wheelset_forces = static_cast<std::uint8_t>(s.wheelset_forces);
  out.node.schedule = s.mode == "sync" ? node::Schedule::sync : node::Schedule::periodic;
  out.node.input_timeout_ns = static_cast<std::int64_t>(s.timeout_ms * 1e6);
  return out;
}

}  // namespace tread::cli
