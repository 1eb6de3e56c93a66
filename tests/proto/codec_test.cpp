#include "proto/codec.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

RigData sample_rig() {
  RigData d{};
  for (std::size_t i = 0; i < kMaxWheels; ++i) {
    const auto k = static_cast<float>(i);
    d.wheels[i] = WheelInput{0.05F * k - 0.07F, -0.1F + 0.03F * k, 0.01F * k, 3000.0F + 500.0F * k,
                             16.7F + k,         50.0F - k,         i % 2 == 0};
  }
  d.wheelsets[0] = WheelsetInput{-3.25F, 0.002F, true};
  d.wheelsets[1] = WheelsetInput{7.5F, -0.001F, false};
  d.rig_cycle = 123456789U;
  d.command = Command{true, false, 3, 7};
  return d;
}

NodeData sample_node() {
  NodeData d{};
  for (std::size_t i = 0; i < kMaxWheels; ++i) {
    const auto k = static_cast<float>(i);
    d.wheels[i] = WheelOutput{
        -1817.0F + 10.0F * k,        1112.0F - k, 1.35F * k, -11.7F, -9.9F, 0.3F + 0.001F * k,
        static_cast<std::uint8_t>(i)};
  }
  d.wheelsets[0] = WheelsetOutput{460.1234F, 459.8766F, 0.2468F, 0.05F, -0.04F, 1};
  d.wheelsets[1] = WheelsetOutput{466.5F, 458.0F, 8.5F, 1.2F, 0.03F, 2};
  d.status = NodeStatusData{0x5, 40000, 3, 17, 0x12, 0x21};
  return d;
}

void expect_rig_equal(const RigData& a, const RigData& b, Layout layout) {
  for (std::size_t i = 0; i < kMaxWheels; ++i) {
    EXPECT_NEAR(a.wheels[i].kappa, b.wheels[i].kappa, 2.5e-5);
    EXPECT_NEAR(a.wheels[i].alpha_rad, b.wheels[i].alpha_rad, 1e-5);
    EXPECT_NEAR(a.wheels[i].gamma_rad, b.wheels[i].gamma_rad, 5e-6);
    EXPECT_NEAR(a.wheels[i].fz_n, b.wheels[i].fz_n, 0.5);
    EXPECT_NEAR(a.wheels[i].vx_mps, b.wheels[i].vx_mps, 0.005);
    EXPECT_NEAR(a.wheels[i].omega_radps, b.wheels[i].omega_radps, 0.005);
    EXPECT_EQ(a.wheels[i].omega_valid, b.wheels[i].omega_valid);
  }
  for (std::size_t j = 0; j < kMaxWheelsets; ++j) {
    EXPECT_NEAR(a.wheelsets[j].lateral_mm, b.wheelsets[j].lateral_mm, 5e-4);
    EXPECT_NEAR(a.wheelsets[j].yaw_rad, b.wheelsets[j].yaw_rad, 5e-6);
    EXPECT_EQ(a.wheelsets[j].yaw_valid, b.wheelsets[j].yaw_valid);
  }
  EXPECT_EQ(a.rig_cycle, b.rig_cycle);
  EXPECT_EQ(a.command.enable, b.command.enable);
  EXPECT_EQ(a.command.tyre_set, b.command.tyre_set);
  EXPECT_EQ(a.command.profile_set, b.command.profile_set);
  static_cast<void>(layout);
}

class CodecLayout : public ::testing::TestWithParam<Layout> {};

TEST_P(CodecLayout, EveryRigMessageRoundTrips) {
  const Layout layout = GetParam();
  const RigData sent = sample_rig();
  RigData got{};
  std::uint8_t counter = 0;
  for (const MessageSpec& m : messages(layout)) {
    if (m.direction != Direction::rig_to_node) {
      continue;
    }
    CanFrame f{};
    ASSERT_EQ(encode(m, sent, counter, f), Status::ok) << m.name;
    EXPECT_EQ(f.id, m.id);
    EXPECT_EQ(f.len, m.len);
    EXPECT_EQ(f.fd, m.fd);
    E2eReceiver rx{};
    EXPECT_TRUE(e2e_accepted(e2e_check(f, m.data_id(), rx)));
    EXPECT_EQ(e2e_counter_of(f), counter);
    ASSERT_EQ(decode(m, f, got), Status::ok);
    counter = static_cast<std::uint8_t>((counter + 1U) % kE2eCounterModulo);
  }
  expect_rig_equal(sent, got, layout);
}

TEST_P(CodecLayout, EveryNodeMessageRoundTrips) {
  const Layout layout = GetParam();
  const NodeData sent = sample_node();
  NodeData got{};
  for (const MessageSpec& m : messages(layout)) {
    if (m.direction != Direction::node_to_rig) {
      continue;
    }
    CanFrame f{};
    ASSERT_EQ(encode(m, sent, 9, f), Status::ok) << m.name;
    ASSERT_EQ(decode(m, f, got), Status::ok);
  }
  for (std::size_t i = 0; i < kMaxWheels; ++i) {
    EXPECT_NEAR(got.wheels[i].fx_n, sent.wheels[i].fx_n, 0.5);
    EXPECT_NEAR(got.wheels[i].fy_n, sent.wheels[i].fy_n, 0.5);
    EXPECT_NEAR(got.wheels[i].mz_nm, sent.wheels[i].mz_nm, 0.025);
    EXPECT_NEAR(got.wheels[i].mx_nm, sent.wheels[i].mx_nm, 0.025);
    EXPECT_NEAR(got.wheels[i].my_nm, sent.wheels[i].my_nm, 0.025);
    EXPECT_NEAR(got.wheels[i].rl_m, sent.wheels[i].rl_m, 5e-6);
    EXPECT_EQ(got.wheels[i].status, sent.wheels[i].status);
  }
  for (std::size_t j = 0; j < kMaxWheelsets; ++j) {
    EXPECT_NEAR(got.wheelsets[j].r_left_mm, sent.wheelsets[j].r_left_mm, 1e-4);
    EXPECT_NEAR(got.wheelsets[j].r_right_mm, sent.wheelsets[j].r_right_mm, 1e-4);
    EXPECT_NEAR(got.wheelsets[j].delta_r_mm, sent.wheelsets[j].delta_r_mm, 5e-4);
    EXPECT_NEAR(got.wheelsets[j].gamma_left_rad, sent.wheelsets[j].gamma_left_rad, 5e-5);
    EXPECT_NEAR(got.wheelsets[j].gamma_right_rad, sent.wheelsets[j].gamma_right_rad, 5e-5);
    EXPECT_EQ(got.wheelsets[j].status, sent.wheelsets[j].status);
  }
  EXPECT_EQ(got.status.state, sent.status.state);
  EXPECT_EQ(got.status.cycle, sent.status.cycle);
  EXPECT_EQ(got.status.overruns, sent.status.overruns);
  EXPECT_EQ(got.status.rejected, sent.status.rejected);
  EXPECT_EQ(got.status.stale_mask, sent.status.stale_mask);
  EXPECT_EQ(got.status.clamp_mask, sent.status.clamp_mask);
}

INSTANTIATE_TEST_SUITE_P(Layouts, CodecLayout, ::testing::Values(Layout::classic, Layout::fd));

TEST(Codec, SaturationIsReportedButFrameStillSent) {
  NodeData d{};
  d.wheels[0].fx_n = 1e6F;
  d.wheels[0].fy_n = std::nanf("");
  CanFrame f{};
  EXPECT_EQ(encode(messages(Layout::classic)[13], d, 0, f), Status::out_of_range);
  NodeData got{};
  ASSERT_EQ(decode(messages(Layout::classic)[13], f, got), Status::ok);
  EXPECT_EQ(got.wheels[0].fx_n, 32767.0F);
  EXPECT_EQ(got.wheels[0].fy_n, 0.0F);
}

TEST(Codec, WrongLengthAndDirectionAreRejected) {
  const MessageSpec& slip = *find_message(Layout::classic, 0x100);
  CanFrame f{};
  f.len = 7;
  RigData rig{};
  EXPECT_EQ(decode(slip, f, rig), Status::invalid_argument);
  NodeData node{};
  f.len = 8;
  EXPECT_EQ(decode(slip, f, node), Status::invalid_argument);
  EXPECT_EQ(encode(slip, node, 0, f), Status::invalid_argument);
}

TEST(Messages, IdsAreUniqueAndFindable) {
  for (const Layout layout : {Layout::classic, Layout::fd}) {
    const auto all = messages(layout);
    for (std::size_t a = 0; a < all.size(); ++a) {
      EXPECT_EQ(find_message(layout, all[a].id), &all[a]);
      EXPECT_EQ(message_index(layout, all[a]), a);
      for (std::size_t b = a + 1; b < all.size(); ++b) {
        EXPECT_NE(all[a].id, all[b].id);
      }
    }
  }
  EXPECT_EQ(find_message(Layout::classic, 0x7FF), nullptr);
}

}  // namespace
}  // namespace tread::proto
