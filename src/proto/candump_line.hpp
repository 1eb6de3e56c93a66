#pragma once
// One line of a candump log (can-utils `candump -l`, read by canplayer), without heap or I/O, so
// the host tools and the firmware image read and write logs with the same code:
//   (seconds.micros) iface ID#DATA         classic; ID 3 hex digits (11-bit) or 8 (29-bit)
//   (seconds.micros) iface ID##FDATA       FD; F = one hex digit of flags (1 = BRS)
// Error frames carry CAN_ERR_FLAG (0x20000000) in an 8-digit ID.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "proto/can_frame.hpp"

namespace tread::proto {

/// Room for any formatted line and its '\0': a 19-digit timestamp, a 32-character interface, an
/// FD frame of 64 bytes.
inline constexpr std::size_t kCandumpLineMax = 208;

/// One log line (no newline, '\0'-terminated) into `out`, which must hold kCandumpLineMax
/// characters; the interface name is cut at 32 characters. Returns the length.
std::size_t format_candump_line(const CanFrame& frame, std::int64_t time_ns,
                                std::string_view interface, char* out) noexcept;

/// What was wrong with a line that did not parse.
enum class CandumpError : std::uint8_t {
  none,
  not_a_frame,      ///< no '(' at the start
  bad_timestamp,    ///< no ')' or '.' in the timestamp, or seconds beyond int64 nanoseconds
  bad_micros,       ///< the timestamp is not seconds.6-digit micros
  no_interface,     ///< nothing after the interface name
  bad_id_length,    ///< the ID is not 3 or 8 hex digits followed by '#'
  id_not_hex,       ///< a non-hex digit in the ID
  no_fd_flags,      ///< '##' without a flags digit
  odd_data,         ///< an odd number of data digits
  bad_data_length,  ///< more data than the frame type holds, or not a valid FD length
  data_not_hex,     ///< a non-hex digit in the data
};

/// A short, static description ("malformed timestamp", ...).
const char* describe(CandumpError error) noexcept;

struct CandumpLine {
  std::int64_t time_ns{0};     ///< microsecond resolution
  std::string_view interface;  ///< a view into the parsed text
  CanFrame frame{};            ///< frame.timestamp_ns = time_ns
  std::size_t data_len{0};     ///< data bytes written (for a bad_data_length message)
};

/// Parses one line (no newline; candump's trailing direction flag " R"/" T" is ignored).
/// @retval CandumpError::none  `out` holds the frame
/// @retval any other           the line is malformed (`out` is partly filled)
CandumpError parse_candump_line(std::string_view line, CandumpLine& out) noexcept;

}  // namespace tread::proto
