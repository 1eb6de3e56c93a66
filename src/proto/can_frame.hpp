#pragma once
// A CAN / CAN FD frame as plain data: what the protocol encodes into and the HAL moves.

#include <array>
#include <cstdint>

namespace tread::proto {

inline constexpr std::uint8_t kClassicMaxLen = 8;
inline constexpr std::uint8_t kFdMaxLen = 64;

struct CanFrame {
  std::uint32_t id{0};          ///< 11-bit or 29-bit identifier (without flag bits)
  bool extended{false};         ///< 29-bit identifier
  bool fd{false};               ///< CAN FD frame (up to 64 bytes)
  bool bit_rate_switch{false};  ///< FD only: BRS
  bool error{false};    ///< error frame reported by the controller (classic, id = error class)
  std::uint8_t len{0};  ///< payload length in bytes
  std::array<std::uint8_t, kFdMaxLen> data{};
  std::int64_t timestamp_ns{-1};  ///< receive time (kernel timestamp when available), -1 if none
};

/// The valid CAN FD payload lengths are 0..8, 12, 16, 20, 24, 32, 48, 64.
[[nodiscard]] constexpr bool is_valid_fd_length(std::uint8_t len) noexcept {
  return len <= 8U || len == 12U || len == 16U || len == 20U || len == 24U || len == 32U ||
         len == 48U || len == 64U;
}

}  // namespace tread::proto
