#include "log_writer.hpp"

#include <span>

namespace tread::firmware {

namespace semihost = hal::semihost;

Status LogWriter::open(std::string_view path, std::string_view interface) noexcept {
  const Result<semihost::Handle> opened = semihost::open(path, semihost::Mode::write_binary);
  if (!opened.ok()) {
    return opened.status;
  }
  file_ = opened.value;
  open_ = true;
  interface_len_ = interface.size() < interface_.size() ? interface.size() : interface_.size();
  for (std::size_t i = 0; i < interface_len_; ++i) {
    interface_[i] = interface[i];
  }
  used_ = 0;
  status_ = Status::ok;
  return Status::ok;
}

void LogWriter::write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
  if (!open_) return;
  if (buffer_.size() - used_ < proto::kCandumpLineMax + 1) {
    flush();
  }
  const std::size_t n = proto::format_candump_line(
      frame, time_ns, std::string_view(interface_.data(), interface_len_), buffer_.data() + used_);
  buffer_[used_ + n] = '\n';
  used_ += n + 1;
}

void LogWriter::flush() noexcept {
  if (used_ == 0) return;
  const Status written = semihost::write(file_, std::span<const char>(buffer_.data(), used_));
  if (status_ == Status::ok) status_ = written;
  used_ = 0;
}

Status LogWriter::close() noexcept {
  if (!open_) return status_;
  flush();
  const Status closed = semihost::close(file_);
  if (status_ == Status::ok) status_ = closed;
  open_ = false;
  return status_;
}

}  // namespace tread::firmware
