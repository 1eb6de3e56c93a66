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
class CandumpWriter {
 public:
  CandumpWriter() = default;
  CandumpWriter(const CandumpWriter&) = delete;
  CandumpWriter& operator=(const CandumpWriter&) = delete;
  ~CandumpWriter();

  /// Opens (truncates) `path`; throws std::runtime_error if it cannot.
  void open(const std::filesystem::path& path, std::string interface);
  [[nodiscard]] bool is_open() const noexcept { return file_ != nullptr; }
  void write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept;
  void close() noexcept;

 private:
  std::FILE* file_{nullptr};
  std::string interface_;
  std::vector<char> buffer_;
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
