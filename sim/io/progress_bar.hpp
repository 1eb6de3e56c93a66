#pragma once
// A one-line progress bar for long runs of a host tool (host side): on a terminal only, so that
// logs, pipes and the tests' captured stderr never see it.
//
//   [##########----------]  48 %  rows 1 048 576  1.21 M rows/s
//
// Drawn with '\r' at most ten times a second, from `delay_s` after the start on (a short run draws
// nothing), and erased by finish(). The caller passes the elapsed time: the bar reads no clock.

#include <cstdint>
#include <iosfwd>

namespace tread::host {

class ProgressBar {
 public:
  /// `terminal`: whether `out` is a terminal (see stderr_is_terminal()); false: the bar is off.
  /// `total_bytes`: the input's size (0: unknown, the bar shows rows and rate only).
  ProgressBar(std::ostream& out, bool terminal, std::uint64_t total_bytes, double delay_s = 1.0);

  /// `bytes` of the input and `rows` done after `elapsed_s` seconds.
  void update(std::uint64_t bytes, std::uint64_t rows, double elapsed_s);
  /// Erases the bar if it was drawn.
  void finish();

 private:
  std::ostream& out_;
  bool on_;
  std::uint64_t total_bytes_;
  double delay_s_;
  double drawn_at_s_ = -1.0;  ///< when last drawn; < 0: never
};

/// Whether standard error is a terminal (isatty).
bool stderr_is_terminal();

}  // namespace tread::host
