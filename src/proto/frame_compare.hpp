#pragma once
// Whether two frames of the protocol say the same thing up to the protocol's resolution: every
// physical signal within a number of quantisation steps (raw units), every integer signal (flags,
// counters, masks, status bits) equal, and the second frame's E2E CRC valid. This is how a float
// target's answers are checked against the host's: the same arithmetic in another order may round
// a value to the neighbouring raw step, never further.

#include <cstdint>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/messages.hpp"
#include "proto/signal.hpp"

namespace tread::proto {

struct FrameComparison {
  Status status{Status::ok};
  const SignalSpec* worst{nullptr};  ///< the signal that differs most (nullptr if none differs)
  std::int64_t worst_steps{0};       ///< its difference in raw steps
};

/// Compares `actual` with `expected`, both in `layout`.
/// @retval Status::ok                same message; signals within `max_steps`, integers equal
/// @retval Status::out_of_range      a physical signal differs by more than `max_steps`, or an
///                                   integer signal differs (`worst` names it)
/// @retval Status::bad_crc           `actual`'s E2E CRC does not match its payload
/// @retval Status::invalid_argument  not the same message (identifier, length, FD flag), or not
///                                   a message of `layout`
FrameComparison compare_frames(Layout layout, const CanFrame& expected, const CanFrame& actual,
                               std::int64_t max_steps) noexcept;

}  // namespace tread::proto
