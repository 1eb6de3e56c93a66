#include "io/progress_bar.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include <unistd.h>

namespace tread::host {

namespace {

constexpr int kWidth = 20;                 // characters of the bar
constexpr double kRedrawInterval_s = 0.1;  // at most ten times a second

// 1048576 → "1 048 576".
std::string grouped(std::uint64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

std::string rate_text(double rows_per_s) {
  char buffer[32];
  if (rows_per_s >= 1e6) {
    std::snprintf(buffer, sizeof buffer, "%.2f M rows/s", rows_per_s / 1e6);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.0f k rows/s", rows_per_s / 1e3);
  }
  return buffer;
}

}  // namespace

ProgressBar::ProgressBar(std::ostream& out, bool terminal, std::uint64_t total_bytes,
                         double delay_s)
    : out_(out), on_(terminal), total_bytes_(total_bytes), delay_s_(delay_s) {}

void ProgressBar::update(std::uint64_t bytes, std::uint64_t rows, double elapsed_s) {
  if (!on_ || elapsed_s < delay_s_) return;
  if (drawn_at_s_ >= 0.0 && elapsed_s - drawn_at_s_ < kRedrawInterval_s) return;
  drawn_at_s_ = elapsed_s;
  std::string line = "\r";
  if (total_bytes_ > 0) {
    const double fraction =
        std::min(1.0, static_cast<double>(bytes) / static_cast<double>(total_bytes_));
    const int filled = static_cast<int>(fraction * kWidth);
    line += '[' + std::string(static_cast<std::size_t>(filled), '#') +
            std::string(static_cast<std::size_t>(kWidth - filled), '-') + "] ";
    char percent[8];
    std::snprintf(percent, sizeof percent, "%3d %%", static_cast<int>(fraction * 100.0));
    line += percent;
    line += "  ";
  }
  line += "rows " + grouped(rows);
  if (elapsed_s > 0.0) line += "  " + rate_text(static_cast<double>(rows) / elapsed_s);
  line += "\033[K";  // erase what a longer previous line left
  out_ << line << std::flush;
}

void ProgressBar::finish() {
  if (drawn_at_s_ < 0.0) return;
  out_ << "\r\033[K" << std::flush;
  drawn_at_s_ = -1.0;
}

bool stderr_is_terminal() {
  return ::isatty(STDERR_FILENO) == 1;
}

}  // namespace tread::host
