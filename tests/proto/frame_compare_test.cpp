#include "proto/frame_compare.hpp"

#include <gtest/gtest.h>

#include <span>

#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

const MessageSpec& wheel_message() {
  const MessageSpec* m = find_message(Layout::classic, 0x180);
  EXPECT_NE(m, nullptr);
  return *m;
}

CanFrame wheel_frame() {
  NodeData data;
  data.wheels[0] = WheelOutput{1234.5F, -321.0F, 12.0F, 1.0F, 2.0F, 0.3F, 0};
  CanFrame f;
  EXPECT_EQ(encode(wheel_message(), data, 3, f), Status::ok);
  return f;
}

/// `frame` with signal `role` moved by `steps` raw steps, re-protected.
CanFrame moved(CanFrame f, Role role, std::int64_t steps) {
  const MessageSpec& m = wheel_message();
  for (const SignalSpec& s : m.signals) {
    if (s.role == role) {
      const std::span<std::uint8_t> bytes(f.data.data(), f.len);
      EXPECT_EQ(encode_raw_signal(s, decode_raw_signal(s, bytes) + steps, bytes), Status::ok);
    }
  }
  e2e_protect(f, m.data_id(), e2e_counter_of(f));
  return f;
}

TEST(FrameCompare, OneQuantisationStepPassesTwoDoNot) {
  const CanFrame a = wheel_frame();
  EXPECT_EQ(compare_frames(Layout::classic, a, a, 1).status, Status::ok);
  const FrameComparison one = compare_frames(Layout::classic, a, moved(a, Role::fx, -1), 1);
  EXPECT_EQ(one.status, Status::ok);
  ASSERT_NE(one.worst, nullptr);
  EXPECT_EQ(one.worst->role, Role::fx);
  EXPECT_EQ(one.worst_steps, 1);
  const FrameComparison two = compare_frames(Layout::classic, a, moved(a, Role::fx, 2), 1);
  EXPECT_EQ(two.status, Status::out_of_range);
  EXPECT_EQ(two.worst->role, Role::fx);
  EXPECT_EQ(two.worst_steps, 2);
}

TEST(FrameCompare, IntegerSignalsMustBeEqual) {
  const CanFrame a = wheel_frame();
  const FrameComparison c = compare_frames(Layout::classic, a, moved(a, Role::counter, 1), 1);
  EXPECT_EQ(c.status, Status::out_of_range);
  EXPECT_EQ(c.worst->role, Role::counter);
}

TEST(FrameCompare, BadCrcAndOtherMessagesAreCaught) {
  const CanFrame a = wheel_frame();
  CanFrame bad = a;
  bad.data[0] = static_cast<std::uint8_t>(bad.data[0] ^ 0x01U);
  EXPECT_EQ(compare_frames(Layout::classic, a, bad, 1).status, Status::bad_crc);
  CanFrame other = a;
  other.id = 0x181;
  EXPECT_EQ(compare_frames(Layout::classic, a, other, 1).status, Status::invalid_argument);
  CanFrame unknown = a;
  unknown.id = 0x7FF;
  EXPECT_EQ(compare_frames(Layout::classic, unknown, unknown, 1).status, Status::invalid_argument);
}

}  // namespace
}  // namespace tread::proto
