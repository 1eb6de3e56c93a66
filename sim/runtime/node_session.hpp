#pragma once
// Running a node from the host: live (SocketCAN or the in-process stub bus, real clock, optional
// GPIO cycle pin and real-time setup, candump log) or as a replay of a candump log on a simulated
// clock, which reproduces the node's transmitted frames bit for bit.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "loop/loop_runner.hpp"
#include "posix/realtime.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {

struct LiveOptions {
  std::string can{"stub"};  ///< "stub" or a SocketCAN interface such as vcan0
  std::int64_t period_us{1000};
  std::uint64_t cycles{0};  ///< 0 = until stopped
  std::string gpio_chip;    ///< empty = no cycle pin
  int gpio_cycle_line{-1};
  hal::RealtimeRequest realtime{};
  std::filesystem::path log;  ///< candump log of every frame received and sent (empty = none)
};

struct SessionReport {
  hal::LoopStats loop{};
  node::NodeCounters counters{};
  std::string notes;  ///< setup messages (RT refusals, GPIO errors, .tir warnings)
  /// SocketCAN only: frames the kernel dropped because the node's receive queue was full
  /// (SO_RXQ_OVFL), and the receive buffer it granted.
  std::optional<std::uint64_t> rx_queue_overflows;
  /// "" when the log (--log, --tx-log) was written whole, else what went wrong (CandumpWriter).
  std::string log_error;
  int receive_buffer_bytes{0};
};

/// Runs until `cycles` computations are done or `stop` becomes true. Throws std::runtime_error for
/// setup failures that make running pointless (no such CAN interface, no CAN in the kernel).
SessionReport run_live(const NodeSettings& settings, const LiveOptions& options,
                       const std::atomic<bool>* stop);

struct ReplayResult {
  SessionReport report;
  std::uint64_t input_frames{0};
  std::uint64_t tx_frames{0};
  std::uint64_t logged_tx_frames{0};  ///< node outputs found in the log
  bool identical{false};              ///< replayed TX == logged TX, line for line
  std::string first_difference;       ///< when not identical
};

/// Replays a log written by `tread node --log` (or `tread demo --log`) on a simulated clock with
/// the log's period. Writes the replayed TX frames to `tx_log` when not empty.
ReplayResult run_replay(const NodeSettings& settings, const std::filesystem::path& log,
                        std::int64_t period_us, const std::filesystem::path& tx_log);

/// A human-readable summary: cycles, overruns, latency percentiles, frame counters.
void print_report(std::ostream& out, const SessionReport& report, bool timing);

/// A percentile of `h` in µs as text: ">= 20000" where it falls in the overflow bucket.
std::string percentile_text(const hal::LatencyHistogram& h, double q);

}  // namespace tread::host
