#pragma once
// What every fuzz target shares: the libFuzzer entry point's signature, reading typed values from
// the input, and the invariants on errors and numbers.
//
// A target is one LLVMFuzzerTestOneInput. Built with clang's -fsanitize=fuzzer (preset `fuzz`) it
// is a libFuzzer binary; built with any compiler together with replay_main.cpp it replays files
// (the seed corpus and every crash input ever found) as a regression test. A broken invariant calls
// fuzz_fail(), which prints what broke and aborts: libFuzzer keeps the input as a crash.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace tread::fuzz {

[[noreturn]] inline void fuzz_fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void fuzz_check(bool ok, const std::string& what) {
  if (!ok) fuzz_fail(what);
}

/// The longest line an error or warning may have: a file's text is quoted through
/// host::text::excerpt (80 characters), so a message stays short whatever the file holds.
constexpr std::size_t kMaxMessageLine = 600;

/// An error or warning as it reaches a terminal: lines of at most kMaxMessageLine bytes beyond the
/// source's name, no control byte but the line break (a binary file's bytes, a 50 MB line quoted
/// whole broke this).
inline void check_message(std::string_view source, std::string_view message) {
  std::size_t line_start = 0;
  for (std::size_t i = 0; i <= message.size(); ++i) {
    if (i == message.size() || message[i] == '\n') {
      if (i - line_start > kMaxMessageLine + source.size()) {
        fuzz_fail("a message line of " + std::to_string(i - line_start) +
                  " bytes: " + std::string(message.substr(line_start, 200)) + "…");
      }
      line_start = i + 1;
      continue;
    }
    const auto c = static_cast<unsigned char>(message[i]);
    if (c < 0x20U || c == 0x7FU) {
      fuzz_fail("a control byte " + std::to_string(c) + " in a message: " + std::string(message));
    }
  }
}

/// Runs `f`; an exception is the clear error bad input must get: derived from std::exception and
/// its message naming the source (`source:line: ...` or `source: ...`). Anything else — a library
/// exception with its own words ("stod", "vector::_M_range_check"), a message without the file —
/// breaks the invariant. std::bad_alloc passes through (libFuzzer reports it as out-of-memory).
/// @param message where given, the exception's message (left as it was if `f` returned)
/// @return true if `f` returned normally
template <typename F>
bool returns_or_names_source(std::string_view source, F&& f, std::string* message = nullptr) {
  try {
    f();
    return true;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    const std::string_view what = e.what();
    if (what.find(source) == std::string_view::npos) {
      fuzz_fail("an error that does not name its source '" + std::string(source) +
                "': " + std::string(what));
    }
    check_message(source, what);
    if (message != nullptr) *message = what;
    return false;
  }
}

/// Reads typed values off the front of the input; past its end every value is 0.
class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : std::uint8_t{0}; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8U) | byte();
    return v;
  }
  std::uint64_t u64() { return (std::uint64_t{u32()} << 32U) | u32(); }
  /// Any double, NaN and infinities included (the raw bits).
  double any_double() {
    const std::uint64_t bits = u64();
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }
  /// A value in [lo, hi] from 32 bits.
  double in_range(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(u32()) / 4294967295.0);
  }
  [[nodiscard]] bool empty() const { return pos_ >= size_; }
  /// The rest of the input as text.
  std::string_view rest() {
    const std::string_view r(reinterpret_cast<const char*>(data_) + pos_, size_ - pos_);
    pos_ = size_;
    return r;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_{0};
};

inline bool is_finite(double v) {
  return std::isfinite(v);
}

}  // namespace tread::fuzz
