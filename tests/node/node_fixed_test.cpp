// The node on the integer-only path (Node<MfTyreChannelFixed, ContactTableChannelFixed>: the
// Fixed64 data model, signals decoded and encoded through signal_fixed.hpp) sends the frames the
// float node sends for the same rig frames, within the fixed path's accuracy: the rig decodes
// forces within 0.1 % of their peak, radii and angles within the integer table's resolution;
// the status bits (clamped, stale) are the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lut/tread_lut.hpp"
#include "node/contact_table_channel.hpp"
#include "node/contact_table_channel_fixed.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/mf_tyre_channel_fixed.hpp"
#include "node/node.hpp"
#include "proto/rig_link.hpp"

namespace tread::node {
namespace {

constexpr std::int64_t kMs = 1'000'000;

template <typename Tyre, typename Contact>
struct Rig {
  Rig(proto::Layout layout, std::array<Tyre, 4> t, std::array<Contact, 2> c)
      : config{layout, 4, 2, 10 * kMs, Schedule::periodic, true, 3},
        tyres(t),
        contacts(c),
        node(config, tyres, contacts),
        rig(layout, 4, 2) {}

  proto::NodeData cycle(std::int64_t now_ns, const proto::RigData& data) {
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = rig.encode_cycle(data, frames);
    for (std::size_t k = 0; k < n; ++k) static_cast<void>(node.receive(frames[k], now_ns));
    std::array<proto::CanFrame, kMaxTxFrames> tx{};
    const std::size_t sent = node.compute(now_ns, tx);
    proto::NodeData out{};
    for (std::size_t k = 0; k < sent; ++k) EXPECT_EQ(rig.receive(tx[k], out), Status::ok);
    return out;
  }

  NodeConfig config;
  std::array<Tyre, 4> tyres;
  std::array<Contact, 2> contacts;
  Node<Tyre, Contact> node;
  proto::RigLink rig;
};

class NodeFixed : public ::testing::TestWithParam<proto::Layout> {};

TEST_P(NodeFixed, SendsWhatTheFloatNodeSendsWithinTheFixedPathsAccuracy) {
  const mf::MfParameters<double> book{};
  const auto pf = mf::convert_parameters<float>(book);
  const auto px = mf::to_fixed_parameters(book);
  const mf::MfOptions options = mf::options_from_use_mode(111).value;
  const lut::ContactPairTable& pair = lut::contact_pairs()[0];
  std::array<MfTyreChannel, 4> tf{};
  std::array<MfTyreChannelFixed, 4> tx{};
  for (std::size_t i = 0; i < 4; ++i) {
    tf[i] = MfTyreChannel(pf, options, i % 2 == 1);  // two wheels with relaxation
    tx[i] = MfTyreChannelFixed(px, options, i % 2 == 1);
  }
  Rig<MfTyreChannel, ContactTableChannel> f(
      GetParam(), tf, {ContactTableChannel(pair.f32), ContactTableChannel(pair.f32)});
  Rig<MfTyreChannelFixed, ContactTableChannelFixed> x(
      GetParam(), tx, {ContactTableChannelFixed(pair.q), ContactTableChannelFixed(pair.q)});
  float peak_fy = 0.0F;
  for (int k = 1; k <= 50; ++k) {
    proto::RigData in;
    const float s = static_cast<float>(k) / 50.0F;
    for (std::size_t i = 0; i < 4; ++i) {
      in.wheels[i] = proto::WheelInput{0.3F * s - 0.1F * static_cast<float>(i),
                                       0.25F * s - 0.1F,
                                       0.01F,
                                       2000.0F + 3000.0F * s,
                                       20.0F,
                                       60.0F,
                                       true};
    }
    in.wheelsets[0] = proto::WheelsetInput{-14.0F + 28.0F * s, 0.0F, false};  // beyond ±12 mm
    in.wheelsets[1] = proto::WheelsetInput{3.0F * s, 0.0F, false};
    const proto::NodeData a = f.cycle(k * kMs, in);
    const proto::NodeData b = x.cycle(k * kMs, in);
    for (std::size_t i = 0; i < 4; ++i) {
      const proto::WheelOutput& wa = a.wheels[i];
      const proto::WheelOutput& wb = b.wheels[i];
      const float force = std::max({std::fabs(wa.fx_n), std::fabs(wa.fy_n), 100.0F});
      EXPECT_NEAR(wb.fx_n, wa.fx_n, 1e-3F * force + 1.0F) << k << ' ' << i;
      EXPECT_NEAR(wb.fy_n, wa.fy_n, 1e-3F * force + 1.0F) << k << ' ' << i;
      EXPECT_NEAR(wb.mz_nm, wa.mz_nm, 0.5F) << k << ' ' << i;
      EXPECT_NEAR(wb.rl_m, wa.rl_m, 2e-4F) << k << ' ' << i;
      EXPECT_EQ(wb.status, wa.status) << k << ' ' << i;
    }
    for (std::size_t j = 0; j < 2; ++j) {
      EXPECT_NEAR(b.wheelsets[j].r_left_mm, a.wheelsets[j].r_left_mm, 0.05F) << k << ' ' << j;
      EXPECT_NEAR(b.wheelsets[j].delta_r_mm, a.wheelsets[j].delta_r_mm, 0.05F) << k << ' ' << j;
      EXPECT_EQ(b.wheelsets[j].status, a.wheelsets[j].status) << k << ' ' << j;
    }
    // Not vacuous: forces computed, not stale; the first wheelset clamped at both ends.
    peak_fy = std::max(peak_fy, std::fabs(b.wheels[0].fy_n));
    EXPECT_EQ(b.status.stale_mask, 0U) << k;
    if (k < 4 || k > 46) {
      EXPECT_NE(b.status.clamp_mask & 0x10U, 0U) << k;
    }
    EXPECT_EQ(b.status.clamp_mask, a.status.clamp_mask) << k;
    EXPECT_EQ(b.status.stale_mask, a.status.stale_mask) << k;
  }
  EXPECT_GT(peak_fy, 1000.0F);
}

INSTANTIATE_TEST_SUITE_P(Layouts, NodeFixed,
                         ::testing::Values(proto::Layout::classic, proto::Layout::fd));

}  // namespace
}  // namespace tread::node
