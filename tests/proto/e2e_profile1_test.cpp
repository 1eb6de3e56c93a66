#include "proto/e2e_profile1.hpp"

#include <gtest/gtest.h>

#include <array>

#include "proto/crc8_j1850.hpp"

namespace tread::proto {
namespace {

CanFrame make_frame(std::uint8_t counter, std::uint16_t data_id = 0x101) {
  CanFrame f{};
  f.id = data_id;
  f.len = 8;
  for (std::uint8_t i = 2; i < 8; ++i) {
    f.data[i] = static_cast<std::uint8_t>(0x10U * i + 1U);
  }
  f.data[1] = 0x70U;  // a signal in the high nibble of byte 1 must survive
  e2e_protect(f, data_id, counter);
  return f;
}

TEST(E2eProfile1, CrcCoversDataIdAndPayloadButNotItself) {
  const CanFrame f = make_frame(3);
  // Independent computation: CRC-8/SAE-J1850 over [id low, id high, bytes 1..7].
  const std::array<std::uint8_t, 9> covered{0x01,      0x01,      f.data[1], f.data[2], f.data[3],
                                            f.data[4], f.data[5], f.data[6], f.data[7]};
  EXPECT_EQ(f.data[0], crc8_sae_j1850(covered));
  EXPECT_EQ(f.data[1], 0x73U);
  EXPECT_EQ(e2e_counter_of(f), 3U);
}

TEST(E2eProfile1, DataIdSeparatesMessagesWithTheSamePayload) {
  CanFrame a = make_frame(1, 0x100);
  CanFrame b = make_frame(1, 0x101);
  b.data[0] = a.data[0];  // same payload CRC under another data ID
  E2eReceiver rx{};
  EXPECT_EQ(e2e_check(b, 0x101, rx), E2eResult::bad_crc);
  EXPECT_TRUE(e2e_accepted(e2e_check(a, 0x100, rx)));
}

TEST(E2eProfile1, EverySingleBitFlipIsDetected) {
  const CanFrame good = make_frame(5);
  for (std::size_t bit = 0; bit < 64; ++bit) {
    CanFrame bad = good;
    bad.data[bit / 8] = static_cast<std::uint8_t>(bad.data[bit / 8] ^ (1U << (bit % 8)));
    E2eReceiver rx{};
    EXPECT_EQ(e2e_check(bad, 0x101, rx), E2eResult::bad_crc) << "bit " << bit;
  }
}

TEST(E2eProfile1, CounterSequence) {
  E2eReceiver rx{};
  EXPECT_EQ(e2e_check(make_frame(13), 0x101, rx), E2eResult::initial);
  EXPECT_EQ(e2e_check(make_frame(14), 0x101, rx), E2eResult::ok);
  EXPECT_EQ(e2e_check(make_frame(0), 0x101, rx), E2eResult::ok);  // wraps 14 -> 0
  EXPECT_EQ(e2e_check(make_frame(0), 0x101, rx), E2eResult::repeated);
  EXPECT_EQ(e2e_check(make_frame(2), 0x101, rx), E2eResult::ok_lost_frames);
  EXPECT_EQ(rx.lost_frames, 1U);
  EXPECT_EQ(e2e_check(make_frame(1), 0x101, rx), E2eResult::wrong_sequence);  // stale
  EXPECT_EQ(e2e_check(make_frame(3), 0x101, rx), E2eResult::ok);  // reference kept: no loss
}

TEST(E2eProfile1, ResynchronisesAfterASenderRestart) {
  E2eReceiver rx{};
  ASSERT_EQ(e2e_check(make_frame(4), 0x101, rx), E2eResult::initial);
  EXPECT_EQ(e2e_check(make_frame(10), 0x101, rx), E2eResult::wrong_sequence);
  EXPECT_EQ(e2e_check(make_frame(11), 0x101, rx), E2eResult::resynchronised);
  EXPECT_EQ(e2e_check(make_frame(12), 0x101, rx), E2eResult::ok);
}

TEST(E2eProfile1, CounterFifteenAndShortFramesAreRejected) {
  CanFrame f = make_frame(0);
  f.data[1] = static_cast<std::uint8_t>((f.data[1] & 0xF0U) | 0x0FU);
  f.data[0] = e2e_crc(f, 0x101);
  E2eReceiver rx{};
  EXPECT_EQ(e2e_check(f, 0x101, rx), E2eResult::bad_counter);
  CanFrame tiny{};
  tiny.len = 1;
  EXPECT_EQ(e2e_check(tiny, 0x101, rx), E2eResult::bad_length);
}

}  // namespace
}  // namespace tread::proto
