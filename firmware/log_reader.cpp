#include "log_reader.hpp"

namespace tread::firmware {

namespace semihost = hal::semihost;

Status LogReader::open(std::string_view path) noexcept {
  const Result<semihost::Handle> opened = semihost::open(path, semihost::Mode::read_binary);
  if (!opened.ok()) {
    return opened.status;
  }
  file_ = opened.value;
  open_ = true;
  begin_ = end_ = 0;
  eof_ = false;
  return Status::ok;
}

Status LogReader::fill() noexcept {
  // Move the unread rest to the front, then read behind it.
  std::size_t n = 0;
  for (std::size_t i = begin_; i < end_; ++i) {
    buffer_[n++] = buffer_[i];
  }
  begin_ = 0;
  end_ = n;
  const Result<std::size_t> got =
      semihost::read(file_, std::span<char>(buffer_.data() + end_, buffer_.size() - end_));
  if (!got.ok()) {
    return got.status;
  }
  end_ += got.value;
  eof_ = got.value == 0;
  return Status::ok;
}

Status LogReader::next(std::string_view& line) noexcept {
  for (;;) {
    for (std::size_t i = begin_; i < end_; ++i) {
      if (buffer_[i] == '\n') {
        std::size_t len = i - begin_;
        if (len > 0 && buffer_[begin_ + len - 1] == '\r') --len;
        line = std::string_view(buffer_.data() + begin_, len);
        begin_ = i + 1;
        return Status::ok;
      }
    }
    if (end_ - begin_ > kMaxLine) {
      return Status::out_of_range;
    }
    if (eof_) {
      if (begin_ == end_) {
        return Status::would_block;
      }
      line = std::string_view(buffer_.data() + begin_, end_ - begin_);  // no final newline
      begin_ = end_;
      return Status::ok;
    }
    const Status filled = fill();
    if (filled != Status::ok) {
      return filled;
    }
  }
}

void LogReader::close() noexcept {
  if (open_) {
    static_cast<void>(semihost::close(file_));
    open_ = false;
  }
}

}  // namespace tread::firmware
