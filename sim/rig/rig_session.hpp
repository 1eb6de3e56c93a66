#pragma once
// `tread rig`: the rig side as its own process, talking to a tread node only through CAN frames. It
// holds one operating point per channel (so every answer of the node can be checked exactly against
// the reference model, whatever the timing between the two processes), sends a cycle every period
// and checks every frame that comes back (E2E, reference values, status).

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>

#include "proto/messages.hpp"

namespace tread::host {

struct RigSettings {
  std::string can{"vcan0"};
  proto::Layout layout{proto::Layout::classic};
  std::uint8_t wheels{4};
  std::filesystem::path tir;  ///< the reference model (the node's tyre file)
  double duration_s{2.0};
  std::int64_t period_us{1000};
};

struct RigReport {
  std::uint64_t cycles{0};
  std::uint64_t frames_sent{0};
  std::uint64_t send_refused{0};
  std::uint64_t node_frames_accepted{0};
  std::uint64_t node_frames_rejected{0};
  std::uint64_t foreign_frames{0};  ///< frames that are not node outputs (floods, other traffic)
  std::uint64_t error_frames{0};
  std::uint64_t answers_checked{0};  ///< wheel outputs compared with the reference
  std::uint64_t stale_answers{0};    ///< wheel outputs flagged stale (zeros), not compared
  double max_force_error_n{0.0};
  double max_moment_error_nm{0.0};
  std::uint32_t node_overruns{0};  ///< from the last NodeStatus
  std::uint32_t node_rejected{0};
  std::uint32_t node_cycle{0};
};

/// Runs the rig over SocketCAN for the duration. Throws std::runtime_error when the link cannot be
/// used.
RigReport run_rig(const RigSettings& settings);
void print_rig_report(std::ostream& out, const RigReport& report);

}  // namespace tread::host
