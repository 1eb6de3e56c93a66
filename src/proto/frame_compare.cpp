#include "proto/frame_compare.hpp"

#include <span>

#include "proto/e2e_profile1.hpp"
#include "proto/role_table.hpp"

namespace tread::proto {

FrameComparison compare_frames(Layout layout, const CanFrame& expected, const CanFrame& actual,
                               std::int64_t max_steps) noexcept {
  FrameComparison result;
  const MessageSpec* m = find_message(layout, expected.id);
  if (m == nullptr || actual.id != expected.id || actual.len != expected.len ||
      actual.fd != expected.fd || actual.extended != expected.extended ||
      actual.error != expected.error || actual.len != m->len) {
    result.status = Status::invalid_argument;
    return result;
  }
  if (actual.len > 0U && e2e_crc(actual, m->data_id()) != actual.data[0]) {
    result.status = Status::bad_crc;
    return result;
  }
  const std::span<const std::uint8_t> a(expected.data.data(), expected.len);
  const std::span<const std::uint8_t> b(actual.data.data(), actual.len);
  for (const SignalSpec& s : m->signals) {
    if (s.role == Role::crc) {
      continue;  // follows from the rest; checked above
    }
    const std::int64_t diff = decode_raw_signal(s, b) - decode_raw_signal(s, a);
    const std::int64_t steps = diff < 0 ? -diff : diff;
    if (steps > result.worst_steps || (steps > 0 && result.worst == nullptr)) {
      result.worst = &s;
      result.worst_steps = steps;
    }
    if (steps > (is_integer_role(s.role) ? 0 : max_steps)) {
      result.status = Status::out_of_range;
      result.worst = &s;
      result.worst_steps = steps;
      return result;
    }
  }
  return result;
}

}  // namespace tread::proto
