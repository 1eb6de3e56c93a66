#pragma once
// Checks the frames the image transmits against an expected candump log (the host's replay of the
// same rig log), frame by frame: same time, same message, every signal within `max_steps` raw
// steps (proto/frame_compare.hpp; 0: bit-identical). Counts the frames that are bit-identical as
// well. Integer arithmetic only.

#include <cstdint>
#include <string_view>

#include "core/status.hpp"
#include "log_reader.hpp"
#include "proto/can_frame.hpp"
#include "proto/messages.hpp"
#include "text_line.hpp"

namespace tread::firmware {

class TxCheck {
 public:
  /// @retval Status::io_error  the host could not open `path`
  /// `max_steps`: how far a signal may be from the expected, in raw steps (integer signals: 0).
  Status open(std::string_view path, proto::Layout layout, std::int64_t max_steps) noexcept;

  /// The next transmitted frame.
  void check(const proto::CanFrame& frame, std::int64_t time_ns) noexcept;

  /// The end of the replay: the expected log must hold no more frames.
  void finish() noexcept;

  [[nodiscard]] bool passed() const noexcept { return failures_ == 0; }
  [[nodiscard]] std::uint64_t frames() const noexcept { return frames_; }
  [[nodiscard]] std::uint64_t identical() const noexcept { return identical_; }
  [[nodiscard]] std::uint64_t failures() const noexcept { return failures_; }
  /// The first failure ("" if none).
  [[nodiscard]] const char* first_failure() noexcept { return first_.c_str(); }

 private:
  /// The next expected frame; false (and a failure noted) at the end or on a bad line.
  bool next_expected(std::int64_t& time_ns, proto::CanFrame& frame) noexcept;
  TextLine& fail() noexcept;

  LogReader expected_;
  proto::Layout layout_{proto::Layout::classic};
  std::int64_t max_steps_{1};
  std::uint64_t frames_{0};
  std::uint64_t identical_{0};
  std::uint64_t failures_{0};
  std::uint64_t line_{0};
  TextLine first_;
  TextLine scratch_;
};

}  // namespace tread::firmware
