#pragma once
// A fixed-size line of text built from strings and integers (no printf: newlib's allocates), for
// the firmware's console messages.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace tread::firmware {

class TextLine {
 public:
  TextLine& operator<<(std::string_view text) noexcept {
    for (const char c : text) put(c);
    return *this;
  }
  TextLine& operator<<(std::uint64_t value) noexcept {
    char digits[20];
    int n = 0;
    do {
      digits[n++] = static_cast<char>('0' + value % 10U);
      value /= 10U;
    } while (value != 0U);
    while (n > 0) put(digits[--n]);
    return *this;
  }
  /// '\0'-terminated; cut at the capacity.
  [[nodiscard]] const char* c_str() noexcept {
    text_[used_] = '\0';
    return text_.data();
  }

 private:
  void put(char c) noexcept {
    if (used_ + 1 < text_.size()) text_[used_++] = c;
  }
  std::array<char, 320> text_{};
  std::size_t used_{0};
};

}  // namespace tread::firmware
