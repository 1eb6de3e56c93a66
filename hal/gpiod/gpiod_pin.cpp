#include "gpiod/gpiod_pin.hpp"

#include <gpiod.h>

#include <cerrno>
#include <cstring>

namespace tread::hal {

GpiodPin::~GpiodPin() {
  close();
}

void GpiodPin::close() noexcept {
  if (line_ != nullptr) {
    ::gpiod_line_release(line_);
    line_ = nullptr;
  }
  if (chip_ != nullptr) {
    ::gpiod_chip_close(chip_);
    chip_ = nullptr;
  }
}

Status GpiodPin::open(std::string_view chip, unsigned int line, std::string_view consumer) {
  close();
  const std::string chip_name(chip);
  chip_ = ::gpiod_chip_open_lookup(chip_name.c_str());
  if (chip_ == nullptr) {
    error_ = chip_name + ": no such GPIO chip (" + std::strerror(errno) + ")";
    return Status::invalid_argument;
  }
  line_ = ::gpiod_chip_get_line(chip_, line);
  if (line_ == nullptr) {
    error_ = chip_name + " line " + std::to_string(line) + ": no such line (chip has " +
             std::to_string(::gpiod_chip_num_lines(chip_)) + " lines)";
    close();
    return Status::invalid_argument;
  }
  const std::string consumer_name(consumer);
  if (::gpiod_line_request_output(line_, consumer_name.c_str(), 0) != 0) {
    error_ = chip_name + " line " + std::to_string(line) + ": cannot request as output (" +
             std::strerror(errno) + ")";
    line_ = nullptr;  // not requested: nothing to release
    close();
    return Status::io_error;
  }
  error_.clear();
  return Status::ok;
}

Status GpiodPin::set(bool level) noexcept {
  if (line_ == nullptr) {
    return Status::unsupported;
  }
  return ::gpiod_line_set_value(line_, level ? 1 : 0) == 0 ? Status::ok : Status::io_error;
}

}  // namespace tread::hal
