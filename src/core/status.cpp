#include "core/status.hpp"

namespace tread {

const char* to_string(Status status) noexcept {
  switch (status) {
    case Status::ok:
      return "ok";
    case Status::out_of_range:
      return "out of range";
    case Status::invalid_argument:
      return "invalid argument";
    case Status::bad_crc:
      return "bad CRC";
    case Status::bad_counter:
      return "bad counter";
    case Status::timeout:
      return "timeout";
    case Status::would_block:
      return "would block";
    case Status::io_error:
      return "I/O error";
    case Status::unsupported:
      return "unsupported";
    case Status::non_finite:
      return "non-finite result";
  }
  return "unknown status";
}

}  // namespace tread
