#pragma once
// End-to-end protection in the manner of AUTOSAR E2E profile 1: byte 0 = CRC, low nibble of byte 1
// = counter (0..14; 15 is never sent), data ID per message included in the CRC.
//
// CRC = CRC-8/SAE-J1850 (poly 0x1D, init 0xFF, xorout 0xFF) over
//       [data ID low byte, data ID high byte, frame bytes 1 .. len-1]
// (profile 1 with DataIDMode "both"; the chained Crc_CalculateCRC8 calls of the AUTOSAR library
// give exactly this one-shot CRC).

#include <cstdint>

#include "core/status.hpp"
#include "proto/can_frame.hpp"

namespace tread::proto {

inline constexpr std::uint8_t kE2eCounterModulo = 15;  ///< counter runs 0..14

/// The CRC of a frame's payload as defined above (byte 0 is not included).
[[nodiscard]] std::uint8_t e2e_crc(const CanFrame& frame, std::uint16_t data_id) noexcept;

/// Writes the counter (low nibble of byte 1, high nibble kept) and then the CRC into byte 0.
void e2e_protect(CanFrame& frame, std::uint16_t data_id, std::uint8_t counter) noexcept;

/// Receiver state of one protected message.
struct E2eReceiver {
  std::uint8_t last_counter{0};
  bool synchronised{false};      ///< a valid reference counter exists
  std::uint8_t max_delta{3};     ///< largest accepted counter step (1 + frames allowed to be lost)
  std::uint32_t lost_frames{0};  ///< frames missing between accepted ones (counter gaps)
  std::uint8_t candidate_counter{0};  ///< counter of the last out-of-sequence frame
  bool has_candidate{false};
};

enum class E2eResult : std::uint8_t {
  ok,              ///< accepted
  ok_lost_frames,  ///< accepted; counter skipped 1..max_delta-1 values
  initial,         ///< first frame after start or resynchronisation: accepted
  bad_length,      ///< shorter than the header (2 bytes)
  bad_crc,         ///< CRC mismatch: rejected
  bad_counter,     ///< counter value 15: rejected
  repeated,        ///< same counter as the last accepted frame: rejected
  wrong_sequence,  ///< counter jumped by more than max_delta (or went back): rejected, reference
                   ///< kept
  resynchronised,  ///< in sequence with the previous out-of-sequence frame: accepted as the new
                   ///< reference
};

/// Checks CRC and counter and updates the receiver. Accepted iff e2e_accepted(result).
/// A stale or replayed frame (counter behind the reference) is rejected and costs no valid frame:
/// the reference is kept. When the sender really restarted its counter, two consecutive frames that
/// are in sequence with each other re-establish the reference (the second one is accepted).
[[nodiscard]] E2eResult e2e_check(const CanFrame& frame, std::uint16_t data_id,
                                  E2eReceiver& receiver) noexcept;

[[nodiscard]] constexpr bool e2e_accepted(E2eResult r) noexcept {
  return r == E2eResult::ok || r == E2eResult::ok_lost_frames || r == E2eResult::initial ||
         r == E2eResult::resynchronised;
}

[[nodiscard]] constexpr std::uint8_t e2e_counter_of(const CanFrame& frame) noexcept {
  return static_cast<std::uint8_t>(frame.data[1] & 0x0FU);
}

}  // namespace tread::proto
