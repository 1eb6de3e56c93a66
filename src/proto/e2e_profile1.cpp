#include "proto/e2e_profile1.hpp"

#include <array>
#include <cstring>
#include <span>

#include "proto/crc8_j1850.hpp"

namespace tread::proto {

std::uint8_t e2e_crc(const CanFrame& frame, std::uint16_t data_id) noexcept {
  // One pass over [data ID low, data ID high, bytes 1..n-1] (the CRC's sliced loop runs 8 bytes
  // per step: a classic frame is one step and one byte).
  std::array<std::uint8_t, 2U + sizeof(frame.data)> buffer;  // only [0, len + 1) is read
  buffer[0] = static_cast<std::uint8_t>(data_id & 0xFFU);
  buffer[1] = static_cast<std::uint8_t>(data_id >> 8U);
  const std::size_t len = frame.len > frame.data.size() ? frame.data.size()
                          : frame.len > 1U              ? frame.len
                                                        : 1U;
  std::memcpy(buffer.data() + 2, frame.data.data() + 1, len - 1U);
  return crc8_sae_j1850(std::span<const std::uint8_t>(buffer.data(), len + 1U));
}

void e2e_protect(CanFrame& frame, std::uint16_t data_id, std::uint8_t counter) noexcept {
  frame.data[1] =
      static_cast<std::uint8_t>((frame.data[1] & 0xF0U) | (counter % kE2eCounterModulo));
  frame.data[0] = e2e_crc(frame, data_id);
}

E2eResult e2e_check(const CanFrame& frame, std::uint16_t data_id, E2eReceiver& receiver) noexcept {
  if (frame.len < 2U) {
    return E2eResult::bad_length;
  }
  if (frame.data[0] != e2e_crc(frame, data_id)) {
    return E2eResult::bad_crc;
  }
  const std::uint8_t counter = e2e_counter_of(frame);
  if (counter >= kE2eCounterModulo) {
    return E2eResult::bad_counter;
  }
  if (!receiver.synchronised) {
    receiver.synchronised = true;
    receiver.last_counter = counter;
    return E2eResult::initial;
  }
  const auto step = [](std::uint8_t from, std::uint8_t to) {
    return static_cast<std::uint8_t>((to + kE2eCounterModulo - from) % kE2eCounterModulo);
  };
  const std::uint8_t delta = step(receiver.last_counter, counter);
  if (delta == 0U) {
    return E2eResult::repeated;
  }
  if (delta > receiver.max_delta) {
    const bool follows_candidate = receiver.has_candidate &&
                                   step(receiver.candidate_counter, counter) >= 1U &&
                                   step(receiver.candidate_counter, counter) <= receiver.max_delta;
    if (follows_candidate) {
      receiver.has_candidate = false;
      receiver.last_counter = counter;
      return E2eResult::resynchronised;
    }
    receiver.candidate_counter = counter;
    receiver.has_candidate = true;
    return E2eResult::wrong_sequence;
  }
  receiver.has_candidate = false;
  receiver.last_counter = counter;
  if (delta > 1U) {
    receiver.lost_frames += static_cast<std::uint32_t>(delta - 1U);
    return E2eResult::ok_lost_frames;
  }
  return E2eResult::ok;
}

}  // namespace tread::proto
