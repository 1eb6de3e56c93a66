#pragma once
// The protocol's message catalogue: every frame of the classic-CAN and the CAN FD layout, as tables
// the codec, the node, the rig and the DBC writer share. The DBC files in this folder are generated
// from these tables (`tread proto dbc`) and checked against them by a test.
//
// Every frame starts with the E2E header: byte 0 CRC, low nibble of byte 1 counter
// (e2e_profile1.hpp); the data ID of a message is its CAN identifier. Signals are Intel byte order.

#include <cstdint>
#include <span>

#include "proto/signal.hpp"

namespace tread::proto {

inline constexpr std::uint8_t kMaxWheels = 4;
inline constexpr std::uint8_t kMaxWheelsets = 2;

enum class Layout : std::uint8_t { classic, fd };

/// Identifiers the node and the rig treat specially (the rest is table-driven).
inline constexpr std::uint32_t kCommandId = 0x080;      ///< Command (both layouts)
inline constexpr std::uint32_t kRigCycleId = 0x090;     ///< RigCycle: the classic cycle frame
inline constexpr std::uint32_t kRigInputsFdId = 0x0A0;  ///< RigInputsFD: the FD cycle frame
inline constexpr std::uint32_t kNodeStatusId = 0x0F0;   ///< NodeStatus (both layouts)
enum class Direction : std::uint8_t { rig_to_node, node_to_rig };

struct MessageSpec {
  const char* name;      ///< DBC message name (without the instance suffix)
  std::int8_t instance;  ///< wheel / wheelset index appended as "_<n>", or -1
  std::uint32_t id;      ///< 11-bit identifier, also the E2E data ID
  std::uint8_t len;      ///< payload bytes (8 for classic, a valid FD length for FD)
  bool fd;
  Direction direction;
  std::span<const SignalSpec> signals;

  [[nodiscard]] constexpr std::uint16_t data_id() const noexcept {
    return static_cast<std::uint16_t>(id);
  }
  /// The wheel/wheelset a signal belongs to: its own instance, else the message's.
  [[nodiscard]] constexpr std::int8_t instance_of(const SignalSpec& s) const noexcept {
    return s.instance >= 0 ? s.instance : instance;
  }
};

/// All messages of a layout (both directions), in a fixed order.
[[nodiscard]] std::span<const MessageSpec> messages(Layout layout) noexcept;

/// The message with identifier `id` in `layout`, or nullptr.
[[nodiscard]] const MessageSpec* find_message(Layout layout, std::uint32_t id) noexcept;

/// Index of `message` within messages(layout) (for per-message state arrays).
[[nodiscard]] std::size_t message_index(Layout layout, const MessageSpec& message) noexcept;

/// Upper bound of messages(layout).size() over both layouts.
inline constexpr std::size_t kMaxMessages = 48;

/// Upper bound of the signals of all messages of one layout, over both layouts.
inline constexpr std::size_t kMaxLayoutSignals = 256;

}  // namespace tread::proto
