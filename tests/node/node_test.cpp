#include "node/node.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "node/test_channels.hpp"
#include "proto/rig_link.hpp"

namespace tread::node {
namespace {

using testing::LinearContact;
using testing::LinearTyre;

constexpr std::int64_t kMs = 1'000'000;

struct Harness {
  explicit Harness(proto::Layout layout, std::uint8_t wheels = 4, std::uint8_t wheelsets = 2,
                   Schedule schedule = Schedule::periodic)
      : config{layout, wheels, wheelsets, 10 * kMs, schedule, true, 3},
        node(config, tyres, contacts),
        rig(layout, wheels, wheelsets) {}

  proto::RigData inputs() const {
    proto::RigData d;
    for (std::size_t i = 0; i < proto::kMaxWheels; ++i) {
      d.wheels[i] = proto::WheelInput{
          0.1F * static_cast<float>(i) - 0.15F, 0.02F, 0.01F, 4000.0F, 20.0F, 60.0F, true};
    }
    d.wheelsets[0] = proto::WheelsetInput{2.5F, 0.0F, false};
    d.wheelsets[1] = proto::WheelsetInput{-4.0F, 0.0F, false};
    return d;
  }

  /// One cycle: the rig's frames (optionally tampered), then compute; returns the node's outputs as
  /// the rig decodes them.
  proto::NodeData cycle(std::int64_t now_ns, const proto::RigData& data, bool send = true) {
    std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
    const std::size_t n = send ? rig.encode_cycle(data, frames) : 0U;
    for (std::size_t k = 0; k < n; ++k) {
      last_sync = node.receive(frames[k], now_ns);
    }
    std::array<proto::CanFrame, kMaxTxFrames> tx{};
    const std::size_t sent = node.compute(now_ns, tx);
    proto::NodeData out{};
    for (std::size_t k = 0; k < sent; ++k) {
      EXPECT_EQ(rig.receive(tx[k], out), Status::ok) << "frame " << tx[k].id;
    }
    tx_count = sent;
    return out;
  }

  NodeConfig config;
  std::array<LinearTyre, 4> tyres{};
  std::array<LinearContact, 2> contacts{};
  Node<LinearTyre, LinearContact> node;
  proto::RigLink rig;
  bool last_sync = false;
  std::size_t tx_count = 0;
};

class NodeLayout : public ::testing::TestWithParam<proto::Layout> {};

TEST_P(NodeLayout, InputsReachTheModelsAndOutputsReachTheRig) {
  Harness h(GetParam());
  const proto::RigData in = h.inputs();
  const proto::NodeData out = h.cycle(1 * kMs, in);
  EXPECT_EQ(h.tx_count, GetParam() == proto::Layout::classic ? 13U : 3U);
  EXPECT_TRUE(h.last_sync);  // the cycle frame came last
  for (std::size_t i = 0; i < 4; ++i) {
    LinearTyre reference;
    const TyreResult r = reference.evaluate(h.node.latest_inputs().wheels[i], 0.0F);
    EXPECT_NEAR(out.wheels[i].fx_n, r.fx_n, 0.5F) << i;
    EXPECT_NEAR(out.wheels[i].fy_n, r.fy_n, 0.5F);
    EXPECT_NEAR(out.wheels[i].mz_nm, r.mz_nm, 0.025F);
    EXPECT_NEAR(out.wheels[i].mx_nm, r.mx_nm, 0.025F);
    EXPECT_NEAR(out.wheels[i].my_nm, r.my_nm, 0.025F);
    EXPECT_NEAR(out.wheels[i].rl_m, 0.3F, 1e-5F);
    EXPECT_EQ(out.wheels[i].status, 0U);
    EXPECT_NEAR(h.node.latest_inputs().wheels[i].kappa, in.wheels[i].kappa, 2.5e-5F);
  }
  EXPECT_NEAR(out.wheelsets[0].delta_r_mm, 0.5F, 1e-3F);
  EXPECT_NEAR(out.wheelsets[1].r_left_mm, 459.6F, 1e-3F);
  EXPECT_EQ(out.status.state & proto::kNodeEnabled, proto::kNodeEnabled);
  EXPECT_EQ(out.status.cycle, 1U);
  EXPECT_EQ(h.node.counters().rx_rejected(), 0U);
}

TEST_P(NodeLayout, StaleInputsGiveZeroOutputsAndRecover) {
  Harness h(GetParam());
  const proto::RigData in = h.inputs();
  h.cycle(1 * kMs, in);
  // 10 ms without frames is still fresh; beyond it is stale.
  proto::NodeData out = h.cycle(11 * kMs, in, false);
  EXPECT_EQ(out.wheels[0].status & proto::kStatusStale, 0U);
  out = h.cycle(12 * kMs, in, false);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(out.wheels[i].status, proto::kStatusStale);
    EXPECT_EQ(out.wheels[i].fx_n, 0.0F);
    EXPECT_EQ(out.wheels[i].fy_n, 0.0F);
    EXPECT_GE(h.tyres[i].resets, 1);  // transients restart when inputs return
  }
  EXPECT_EQ(out.wheelsets[1].status, proto::kStatusStale);
  EXPECT_EQ(out.status.stale_mask, 0x3FU);
  out = h.cycle(13 * kMs, in);
  EXPECT_EQ(out.status.stale_mask, 0U);
  EXPECT_EQ(out.wheels[3].status, 0U);
  EXPECT_NE(out.wheels[3].fx_n, 0.0F);
}

TEST_P(NodeLayout, SyncModeStatusNamesTheRigCycleItAnswers) {
  Harness h(GetParam(), 4, 2, Schedule::sync);
  proto::RigData in = h.inputs();
  // An input-timeout computation before any cycle frame answers no rig cycle.
  proto::NodeData out = h.cycle(1 * kMs, in, false);
  EXPECT_EQ(out.status.state & proto::kNodeSyncMode, proto::kNodeSyncMode);
  EXPECT_EQ(out.status.cycle, proto::kNoRigCycle);
  EXPECT_FALSE(proto::answers_rig_cycle(out.status, 0));
  for (const std::uint32_t rig_cycle : {0U, 1U, 7U, 65'535U, 65'536U, 4'000'000'001U}) {
    in.rig_cycle = rig_cycle;
    out = h.cycle(2 * kMs, in);
    EXPECT_TRUE(h.last_sync);
    EXPECT_EQ(out.status.cycle, static_cast<std::uint16_t>(rig_cycle & 0xFFFFU)) << rig_cycle;
    EXPECT_TRUE(proto::answers_rig_cycle(out.status, rig_cycle)) << rig_cycle;
    // The node's own computation before the next cycle frame repeats the last cycle: the rig,
    // waiting for rig_cycle + 1 by then, does not take it.
    out = h.cycle(3 * kMs, in, false);
    EXPECT_EQ(out.status.cycle, static_cast<std::uint16_t>(rig_cycle & 0xFFFFU)) << rig_cycle;
    EXPECT_FALSE(proto::answers_rig_cycle(out.status, rig_cycle + 1U)) << rig_cycle;
  }
  EXPECT_EQ(h.node.counters().rx_rejected(), 0U);
}

TEST_P(NodeLayout, SyncModeEchoIgnoresARejectedCycleFrame) {
  Harness h(GetParam(), 4, 2, Schedule::sync);
  proto::RigData in = h.inputs();
  in.rig_cycle = 41;
  proto::NodeData out = h.cycle(1 * kMs, in);
  ASSERT_EQ(out.status.cycle, 41U);
  // The next cycle's frames with the cycle frame's CRC broken: rejected, so its RigCycle is not
  // what the node answers.
  in.rig_cycle = 42;
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  const std::size_t n = h.rig.encode_cycle(in, frames);
  frames[n - 1].data[0] = static_cast<std::uint8_t>(frames[n - 1].data[0] ^ 0x5AU);
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_FALSE(h.node.receive(frames[k], 2 * kMs));
  }
  EXPECT_EQ(h.node.counters().rx_bad_crc, 1U);
  out = h.cycle(3 * kMs, in, false);
  EXPECT_EQ(out.status.cycle, 41U);
  EXPECT_FALSE(proto::answers_rig_cycle(out.status, 42));
}

// A value beyond its signal's range goes out clamped; the rig counts such frames (the demo and
// rig reports say them: a slip angle of 0.74 rad was sent as 0.655 without a word).
TEST_P(NodeLayout, RigCountsFramesWithASaturatedSignal) {
  Harness h(GetParam());
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::RigData in = h.inputs();
  static_cast<void>(h.rig.encode_cycle(in, frames));
  EXPECT_EQ(h.rig.saturated_frames(), 0U);
  in.wheels[2].alpha_rad = 0.75F;
  static_cast<void>(h.rig.encode_cycle(in, frames));
  EXPECT_EQ(h.rig.saturated_frames(), 1U);
}

TEST_P(NodeLayout, PeriodicModeStatusCountsTheNodesCycles) {
  Harness h(GetParam());
  proto::RigData in = h.inputs();
  in.rig_cycle = 500;
  for (std::uint16_t k = 1; k <= 3; ++k) {
    const proto::NodeData out = h.cycle(k * kMs, in, k != 2);
    EXPECT_EQ(out.status.state & proto::kNodeSyncMode, 0U);
    EXPECT_EQ(out.status.cycle, k);
    EXPECT_TRUE(proto::answers_rig_cycle(out.status, 12345U));  // periodic: cannot tell, any
  }
}

TEST_P(NodeLayout, CorruptedRepeatedAndMisSizedFramesAreRejectedAndCounted) {
  Harness h(GetParam());
  const proto::RigData in = h.inputs();
  h.cycle(1 * kMs, in);
  const proto::RigData before = h.node.latest_inputs();

  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::RigData changed = in;
  changed.wheels[0].kappa = 0.9F;
  const std::size_t n = h.rig.encode_cycle(changed, frames);
  proto::CanFrame bad_crc = frames[0];
  bad_crc.data[3] ^= 0x10U;
  proto::CanFrame short_frame = frames[0];
  short_frame.len = 5;
  EXPECT_FALSE(h.node.receive(bad_crc, 2 * kMs));
  EXPECT_FALSE(h.node.receive(short_frame, 2 * kMs));
  EXPECT_EQ(h.node.latest_inputs().wheels[0].kappa, before.wheels[0].kappa);
  for (std::size_t k = 0; k < n; ++k) {
    static_cast<void>(h.node.receive(frames[k], 2 * kMs));
  }
  EXPECT_NEAR(h.node.latest_inputs().wheels[0].kappa, 0.9F, 1e-4F);
  for (std::size_t k = 0; k < n; ++k) {  // the same frames again: repeated counters
    static_cast<void>(h.node.receive(frames[k], 2 * kMs));
  }
  const NodeCounters& c = h.node.counters();
  EXPECT_EQ(c.rx_bad_crc, 1U);
  EXPECT_EQ(c.rx_bad_length, 1U);
  EXPECT_EQ(c.rx_bad_counter, n);
  EXPECT_EQ(c.lost_frames, 0U);
  std::array<proto::CanFrame, kMaxTxFrames> tx{};
  const std::size_t sent = h.node.compute(2 * kMs, tx);
  proto::NodeData out{};
  for (std::size_t k = 0; k < sent; ++k) {
    ASSERT_EQ(h.rig.receive(tx[k], out), Status::ok);
  }
  EXPECT_EQ(out.status.rejected, 2U + n);
}

TEST_P(NodeLayout, OutOfRangeInputsAreClampedAndFlagged) {
  Harness h(GetParam());
  proto::RigData in = h.inputs();
  in.wheels[2].kappa = 1.4F;
  in.wheelsets[0].lateral_mm = 20.0F;
  const proto::NodeData out = h.cycle(1 * kMs, in);
  EXPECT_EQ(out.wheels[2].status, proto::kStatusClamped);
  EXPECT_NEAR(out.wheels[2].fx_n, 1000.0F, 0.5F);
  EXPECT_EQ(out.wheels[1].status, 0U);
  EXPECT_EQ(out.wheelsets[0].status, proto::kStatusClamped);
  EXPECT_EQ(out.status.clamp_mask, (1U << 2U) | (1U << 4U));
}

TEST_P(NodeLayout, NonFiniteTyreResultIsSentAsZerosFlagged) {
  Harness h(GetParam());
  proto::RigData in = h.inputs();
  in.wheels[1].kappa = 1.4F;  // clamped as well: both bits
  h.tyres[1].defective = true;
  h.tyres[3].defective = true;
  const proto::NodeData out = h.cycle(1 * kMs, in);
  for (const std::size_t i : {std::size_t{1}, std::size_t{3}}) {
    const proto::WheelOutput& w = out.wheels[i];
    for (const float v : {w.fx_n, w.fy_n, w.mz_nm, w.mx_nm, w.my_nm, w.rl_m}) {
      EXPECT_EQ(v, 0.0F) << i;
    }
  }
  EXPECT_EQ(out.wheels[1].status, proto::kStatusClamped | proto::kStatusOutOfRange);
  EXPECT_EQ(out.wheels[3].status, proto::kStatusOutOfRange);
  EXPECT_EQ(out.wheels[0].status, 0U);
  EXPECT_NE(out.wheels[0].fy_n, 0.0F);
  EXPECT_EQ(h.node.counters().non_finite_outputs, 2U);
}

TEST_P(NodeLayout, CommandDisablesEnablesAndResets) {
  Harness h(GetParam());
  const proto::RigData in = h.inputs();
  h.cycle(1 * kMs, in);
  const int resets_enabled = h.tyres[0].resets;
  static_cast<void>(h.node.receive(h.rig.encode_command({false, false, 0, 0}), 2 * kMs));
  proto::NodeData out = h.cycle(2 * kMs, in);
  EXPECT_EQ(out.wheels[0].status, proto::kStatusDisabled);
  EXPECT_GT(h.tyres[0].resets, resets_enabled);  // a disabled node restarts transients
  EXPECT_EQ(out.wheels[0].fx_n, 0.0F);
  EXPECT_EQ(out.status.state & proto::kNodeEnabled, 0U);
  static_cast<void>(h.node.receive(h.rig.encode_command({true, true, 0, 0}), 3 * kMs));
  EXPECT_GE(h.tyres[0].resets, 1);
  EXPECT_EQ(h.node.counters().cycles, 0U);
  out = h.cycle(3 * kMs, in);
  EXPECT_EQ(out.wheels[0].status, 0U);
}

TEST_P(NodeLayout, FewerChannelsSendFewerFrames) {
  Harness h(GetParam(), 2, 0);
  const proto::NodeData out = h.cycle(1 * kMs, h.inputs());
  EXPECT_EQ(h.tx_count, GetParam() == proto::Layout::classic ? 5U : 2U);
  EXPECT_NE(out.wheels[1].fx_n, 0.0F);
  EXPECT_EQ(out.wheels[2].fx_n, 0.0F);
}

TEST_P(NodeLayout, TimeBetweenComputationsReachesTheModel) {
  Harness h(GetParam());
  h.cycle(1 * kMs, h.inputs());
  EXPECT_EQ(h.tyres[0].last_dt_s, 0.0F);
  h.cycle(2 * kMs, h.inputs());
  EXPECT_NEAR(h.tyres[0].last_dt_s, 1e-3F, 1e-9F);
}

INSTANTIATE_TEST_SUITE_P(Layouts, NodeLayout,
                         ::testing::Values(proto::Layout::classic, proto::Layout::fd));

TEST(Node, FramesThatAreNotOursAreIgnoredNotRejected) {
  Harness h(proto::Layout::classic);
  proto::CanFrame foreign{};
  foreign.id = 0x555;
  foreign.len = 8;
  EXPECT_FALSE(h.node.receive(foreign, 0));
  proto::CanFrame own_output{};
  own_output.id = 0x180;
  own_output.len = 8;
  EXPECT_FALSE(h.node.receive(own_output, 0));
  proto::CanFrame error{};
  error.error = true;
  error.id = 0x40;
  EXPECT_FALSE(h.node.receive(error, 0));
  EXPECT_EQ(h.node.counters().rx_ignored, 2U);
  EXPECT_EQ(h.node.counters().rx_error_frames, 1U);
  EXPECT_EQ(h.node.counters().rx_rejected(), 0U);
}

TEST(Node, LostFramesAreCountedFromCounterGaps) {
  Harness h(proto::Layout::fd, 4, 2);
  const proto::RigData in = h.inputs();
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  for (int cycle = 0; cycle < 5; ++cycle) {
    const std::size_t n = h.rig.encode_cycle(in, frames);
    if (cycle == 2) {
      continue;  // the bus lost this cycle's frame
    }
    for (std::size_t k = 0; k < n; ++k) {
      static_cast<void>(h.node.receive(frames[k], cycle * kMs));
    }
  }
  EXPECT_EQ(h.node.counters().lost_frames, 1U);
  EXPECT_EQ(h.node.counters().rx_accepted, 4U);
}

}  // namespace
}  // namespace tread::node
