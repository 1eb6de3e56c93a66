#pragma once
// The rig's side of the protocol: encode a cycle's inputs into frames (each message with its own
// E2E counter, the cycle frame last) and check/decode the node's output frames. Used by the rig
// simulator and by the tests; no heap.

#include <array>
#include <cstddef>
#include <span>

#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"

namespace tread::proto {

class RigLink {
 public:
  /// `wheelset_forces`: how many of the wheelsets get the wheel-rail force inputs
  /// (WheelsetMotion, WheelsetLoad; on FD the one WheelsetMotionFD when any).
  RigLink(Layout layout, std::uint8_t wheels, std::uint8_t wheelsets,
          std::uint8_t wheelset_forces = 0) noexcept;

  /// The input frames of one cycle for the configured channels; the rig's cycle frame (RigCycle or
  /// RigInputsFD) comes last so a node in sync mode computes after it.
  /// @return frames written into `out` (at most kMaxRigFrames)
  std::size_t encode_cycle(const RigData& data, std::span<CanFrame> out) noexcept;

  /// One Command frame.
  CanFrame encode_command(const Command& command) noexcept;

  /// Checks (length, E2E) and decodes one frame from the node into `outputs`.
  /// @retval Status::ok               accepted and decoded
  /// @retval Status::invalid_argument not a node output of this layout (ignored)
  /// @retval Status::bad_crc / bad_counter  rejected
  Status receive(const CanFrame& frame, NodeData& outputs) noexcept;

  [[nodiscard]] std::uint64_t rejected() const noexcept { return rejected_; }
  /// Input frames encode_cycle wrote with a signal saturated at its range (or not finite): the
  /// node received a clamped value (e.g. a slip angle beyond ±0.655 rad).
  [[nodiscard]] std::uint64_t saturated_frames() const noexcept { return saturated_frames_; }
  [[nodiscard]] std::uint64_t accepted() const noexcept { return accepted_; }

  static constexpr std::size_t kMaxRigFrames = 2 * kMaxWheels + 3 * kMaxWheelsets + 1;

 private:
  std::uint8_t next_counter(std::size_t message) noexcept;
  [[nodiscard]] bool wanted(const MessageSpec& m) const noexcept;

  Layout layout_;
  std::uint8_t wheels_;
  std::uint8_t wheelsets_;
  std::uint8_t wheelset_forces_;
  std::array<std::uint8_t, kMaxMessages> counters_{};
  std::array<E2eReceiver, kMaxMessages> receivers_{};
  std::uint64_t rejected_{0};
  std::uint64_t accepted_{0};
  std::uint64_t saturated_frames_{0};
};

}  // namespace tread::proto
