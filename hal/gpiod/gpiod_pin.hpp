#pragma once
// One output line through libgpiod (Debian's 1.6, the v1 API). Satisfies hal::OutputPin.
// A pin that failed to open is inert: set() returns Status::unsupported and the loop runs on.

#include <string>
#include <string_view>

#include "core/status.hpp"
#include "hal_concepts.hpp"

struct gpiod_chip;
struct gpiod_line;

namespace tread::hal {

class GpiodPin {
 public:
  GpiodPin() = default;
  GpiodPin(const GpiodPin&) = delete;
  GpiodPin& operator=(const GpiodPin&) = delete;
  ~GpiodPin();

  /// Opens `chip` (name such as "gpiochip0", or a /dev path) and requests `line` as an output, low.
  /// @retval Status::invalid_argument  no such chip or line; error() says which
  /// @retval Status::io_error          the line could not be requested (busy, permissions)
  Status open(std::string_view chip, unsigned int line, std::string_view consumer = "tread");

  /// @retval Status::unsupported  the pin is not open
  Status set(bool level) noexcept;

  [[nodiscard]] bool is_open() const noexcept { return line_ != nullptr; }
  /// A clear message for the last failure ("gpiochip9: no such GPIO chip (...)").
  [[nodiscard]] const std::string& error() const noexcept { return error_; }

 private:
  void close() noexcept;

  gpiod_chip* chip_{nullptr};
  gpiod_line* line_{nullptr};
  std::string error_;
};

static_assert(OutputPin<GpiodPin>);

}  // namespace tread::hal
