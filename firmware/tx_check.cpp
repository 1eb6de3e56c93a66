#include "tx_check.hpp"

#include "proto/candump_line.hpp"
#include "proto/frame_compare.hpp"

namespace tread::firmware {

Status TxCheck::open(std::string_view path, proto::Layout layout, std::int64_t max_steps) noexcept {
  layout_ = layout;
  max_steps_ = max_steps;
  return expected_.open(path);
}

TextLine& TxCheck::fail() noexcept {
  ++failures_;
  if (failures_ == 1) {
    first_ << "expected log line " << line_ << ": ";
    return first_;
  }
  scratch_ = TextLine{};
  return scratch_;
}

bool TxCheck::next_expected(std::int64_t& time_ns, proto::CanFrame& frame) noexcept {
  std::string_view line;
  for (;;) {
    const Status next = expected_.next(line);
    if (next == Status::would_block) {
      return false;
    }
    ++line_;
    if (next != Status::ok) {
      fail() << "cannot read";
      return false;
    }
    if (!line.empty() && line.front() != '#') break;
  }
  proto::CandumpLine parsed;
  const proto::CandumpError error = proto::parse_candump_line(line, parsed);
  if (error != proto::CandumpError::none) {
    fail() << proto::describe(error);
    return false;
  }
  time_ns = parsed.time_ns;
  frame = parsed.frame;
  return true;
}

void TxCheck::check(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
  ++frames_;
  std::int64_t expected_ns = 0;
  proto::CanFrame expected{};
  if (!next_expected(expected_ns, expected)) {
    if (failures_ == 0) fail() << "the image transmitted more frames than expected";
    return;
  }
  if (expected_ns != time_ns) {
    fail() << "transmitted at another time (cycle schedule differs)";
    return;
  }
  const proto::FrameComparison c = proto::compare_frames(layout_, expected, frame, max_steps_);
  if (c.status == Status::ok) {
    bool same = true;
    for (std::size_t i = 0; i < frame.len; ++i) {
      same = same && frame.data[i] == expected.data[i];
    }
    identical_ += same ? 1U : 0U;
    return;
  }
  TextLine& m = fail();
  if (c.status == Status::out_of_range) {
    m << "signal " << c.worst->name << " differs by " << static_cast<std::uint64_t>(c.worst_steps)
      << " raw steps";
  } else if (c.status == Status::bad_crc) {
    m << "the image's frame has a bad E2E CRC";
  } else {
    m << "another message than expected";
  }
}

void TxCheck::finish() noexcept {
  std::int64_t time_ns = 0;
  proto::CanFrame frame{};
  if (next_expected(time_ns, frame)) {
    fail() << "the image transmitted fewer frames than expected";
  }
  expected_.close();
}

}  // namespace tread::firmware
