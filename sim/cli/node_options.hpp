#pragma once
// Command-line options shared by `tread node` and `tread demo` (header-only: CLI11 is linked only
// into the tread executable).

#include <CLI/CLI.hpp>
#include <map>
#include <string>

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
};

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
  cmd.add_option("--wheelset-forces", s.wheelset_forces,
                 "of the wheelsets, how many also serve the wheel-rail forces (Hertz, Polach creep "
                 "forces, Y/Q, Nadal margin; needs WheelsetMotion and WheelsetLoad from the rig)")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  cmd.add_option("--friction", s.settings.friction,
                 "Polach parameters for the wheel-rail forces: kalker, dry or wet")
      ->check(CLI::IsMember({"kalker", "dry", "wet"}))
      ->capture_default_str();
  cmd.add_option("--mu", s.settings.mu, "wheel-rail friction coefficient mu0 (default: the set's)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--mode", s.mode,
                 "periodic (own schedule) or sync (compute on the rig's cycle frame)")
      ->check(CLI::IsMember({"periodic", "sync"}))
      ->capture_default_str();
  cmd.add_option("--timeout-ms", s.timeout_ms, "input timeout per channel")->capture_default_str();
  cmd.add_option("--use-mode", s.settings.use_mode, "MFeval useMode of the tyre model")
      ->capture_default_str();
  cmd.add_option("--side", s.settings.side, "mounted side: as-measured, left or right")
      ->capture_default_str();
  cmd.add_flag("--fixed", s.settings.fixed,
               "run the node in fixed point, exactly as the FPU-less firmware image does (Q31.32 "
               "Magic Formula, the contact table in integers, integer signal scaling)");
}

/// Turns the parsed options into NodeSettings (call from the command's callback).
inline host::NodeSettings node_settings(NodeCliState& s) {
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
