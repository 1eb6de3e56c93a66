#pragma once
#include <cstdint>

namespace tread::node {

/// Everything the node counts; reported on NodeStatus (saturated) and by the host tools.
struct NodeCounters {
  std::uint64_t cycles{0};
  std::uint64_t rx_frames{0};      ///< every frame offered to receive()
  std::uint64_t rx_accepted{0};    ///< passed length, CRC and counter checks
  std::uint64_t rx_bad_length{0};  ///< our ID, wrong length or FD flag
  std::uint64_t rx_bad_crc{0};
  std::uint64_t rx_bad_counter{0};  ///< repeated, stale/out of sequence, or counter 15
  std::uint64_t rx_ignored{0};      ///< not ours (unknown ID or our own output ID)
  std::uint64_t rx_error_frames{0};
  std::uint64_t lost_frames{0};  ///< gaps in accepted counters (frames the bus lost)
  std::uint64_t tx_frames{0};
  std::uint64_t stale_events{0};       ///< channel-cycles spent stale
  std::uint64_t clamp_events{0};       ///< channel-cycles with clamped inputs
  std::uint64_t saturated_outputs{0};  ///< frames with a saturated output signal
  /// channel results replaced by zeros and flagged (status bit 3): a non-finite model output
  std::uint64_t non_finite_outputs{0};
  std::uint64_t overruns{0};  ///< deadlines missed (reported by the runner)

  [[nodiscard]] std::uint64_t rx_rejected() const noexcept {
    return rx_bad_length + rx_bad_crc + rx_bad_counter;
  }
};

}  // namespace tread::node
