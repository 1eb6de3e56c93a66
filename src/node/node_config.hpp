#pragma once
#include <cstdint>

#include "proto/messages.hpp"

namespace tread::node {

enum class Schedule : std::uint8_t {
  periodic,  ///< own schedule on absolute deadlines
  sync,      ///< compute when the rig's cycle frame arrives (RigCycle / RigInputsFD)
};

struct NodeConfig {
  proto::Layout layout{proto::Layout::classic};
  std::uint8_t wheels{4};     ///< road wheels 0..4
  std::uint8_t wheelsets{0};  ///< rail wheelsets 0..2
  /// A channel without a valid frame this long is stale.
  std::int64_t input_timeout_ns{10'000'000};
  Schedule schedule{Schedule::periodic};
  bool start_enabled{true};       ///< compute from the start (else wait for Command.Enable = 1)
  std::uint8_t e2e_max_delta{3};  ///< largest accepted counter step
  /// Of those, how many also serve the wheel-rail forces (the first ones; 0..wheelsets). They
  /// need WheelsetMotion and WheelsetLoad beside WheelsetIn, and send the RailWheel messages.
  std::uint8_t wheelset_forces{0};
};

}  // namespace tread::node
