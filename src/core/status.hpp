#pragma once
// Errors as values (ARCHITECTURE.md, habit 4): the hot path returns a Status or a Result<T>;
// programming bugs go through TREAD_ASSERT instead.

#include <cstdint>

namespace tread {

enum class Status : std::uint8_t {
  ok = 0,
  out_of_range,  ///< an input lay outside the valid domain; the result was clamped or not produced
  invalid_argument,  ///< an argument was malformed (wrong length, NaN, unknown id)
  bad_crc,           ///< an end-to-end CRC check failed
  bad_counter,       ///< an end-to-end counter was repeated or jumped too far
  timeout,           ///< no valid input within the allowed time
  would_block,       ///< a non-blocking operation had nothing to do / could not proceed now
  io_error,          ///< the operating system refused an operation
  unsupported,       ///< the build or platform does not provide this feature
  non_finite,  ///< a result came out NaN or infinite (e.g. defective parameters); replaced by 0
};

/// A short, static, human-readable name; never allocates.
const char* to_string(Status status) noexcept;

/// A value with a Status. `value` is meaningful only when `ok()`.
template <typename T>
struct Result {
  T value{};
  Status status{Status::ok};

  [[nodiscard]] constexpr bool ok() const noexcept { return status == Status::ok; }
};

}  // namespace tread

/// Programming-bug check of a precondition the caller controls (an index into a fixed set, an output
/// buffer's size); compiled out with NDEBUG, traps otherwise. Never used for bad input, which is
/// an error value.
#ifdef NDEBUG
#define TREAD_ASSERT(cond) static_cast<void>(0)
#else
#define TREAD_ASSERT(cond) ((cond) ? static_cast<void>(0) : __builtin_trap())
#endif
