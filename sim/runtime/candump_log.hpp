#pragma once
// candump logs on the host: whole files, with errors naming file and line. One line's format and
// parsing is the core's heap-free proto/candump_line.hpp, shared with the firmware image.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "proto/can_frame.hpp"
#include "proto/candump_line.hpp"

namespace tread::host {

struct LoggedFrame {
  std::int64_t time_ns{0};  ///< microsecond resolution
  std::string interface;
  proto::CanFrame frame{};
};

using proto::format_candump_line;
using proto::kCandumpLineMax;

/// Parses one line. Throws std::runtime_error naming `where` ("file:line") on malformed input.
LoggedFrame parse_candump_line(std::string_view line, const std::string& where);

/// Reads a whole log; errors name the file and line.
std::vector<LoggedFrame> read_candump_log(const std::filesystem::path& path);

/// Writes frames to a FILE through a fixed buffer: no allocation after open.
///
/// A log is never claimed complete when it is not: the frames go to `<path>.partial`, which gets
/// its name `<path>` only when finish() has written and flushed every one of them. If a write
/// fails (a full disk, a file-size limit) the writer stops writing, and finish() keeps what reached
/// the disk as `<path>.incomplete` and says so; so it does when frames never reached the writer
/// (a full log ring: finish's `dropped_frames`). A target that exists and
/// is not a regular file (/dev/stdout, a pipe) is written directly.
class CandumpWriter {
 public:
  CandumpWriter() = default;
  CandumpWriter(const CandumpWriter&) = delete;
  CandumpWriter& operator=(const CandumpWriter&) = delete;
  /// Without finish(): an abandoned log (an exception mid-run), kept as `<path>.incomplete`.
  ~CandumpWriter();

  /// Opens (truncates) `<path>.partial`; throws std::runtime_error if it cannot.
  void open(const std::filesystem::path& path, std::string interface);
  [[nodiscard]] bool is_open() const noexcept { return file_ != nullptr; }
  void write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept;
  /// Flushes and closes. Returns "" when every frame was written and none was dropped before the
  /// writer (`dropped_frames`, counted by the caller: a full log ring), the log now having its
  /// name; else what went wrong, naming the file and where what reached the disk is.
  [[nodiscard]] std::string finish(std::uint64_t dropped_frames = 0);

 private:
  void abandon() noexcept;

  std::FILE* file_{nullptr};
  std::filesystem::path path_;
  std::filesystem::path partial_;
  std::string interface_;
  std::vector<char> buffer_;
  int errno_{0};  ///< of the first failed write (0: none)
};

/// A loop observer (hal/loop) that writes every frame received and sent to one candump log, so the
/// log holds the node's view of the bus in both directions (what replay needs).
struct CandumpRecorder {
  CandumpWriter* writer{nullptr};
  void on_rx(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
    if (writer != nullptr) writer->write(frame, time_ns);
  }
  void on_tx(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
    if (writer != nullptr) writer->write(frame, time_ns);
  }
};

}  // namespace tread::host
