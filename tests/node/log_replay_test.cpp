#include "node/log_replay.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tread::node {
namespace {

/// Records what the replay does to it.
struct FakeNode {
  NodeConfig cfg{};
  std::vector<std::string> calls;
  bool receive(const proto::CanFrame& frame, std::int64_t now_ns) {
    calls.push_back("rx " + std::to_string(frame.id) + "@" + std::to_string(now_ns));
    return false;
  }
  std::size_t compute(std::int64_t now_ns, std::span<proto::CanFrame> tx) {
    calls.push_back("compute@" + std::to_string(now_ns));
    tx[0] = proto::CanFrame{};
    tx[0].id = proto::kNodeStatusId;
    return 1;
  }
  void note_overrun(std::uint64_t missed) { calls.push_back("overrun " + std::to_string(missed)); }
  [[nodiscard]] const NodeConfig& config() const { return cfg; }
};
static_assert(ReplayableNode<FakeNode>);

struct Sink {
  std::vector<std::int64_t> logged;
  std::vector<std::int64_t> sent;
  void on_logged_tx(const proto::CanFrame& /*frame*/, std::int64_t t) { logged.push_back(t); }
  void on_tx(const proto::CanFrame& /*frame*/, std::int64_t t) { sent.push_back(t); }
};

proto::CanFrame frame(std::uint32_t id) {
  proto::CanFrame f;
  f.id = id;
  f.len = 8;
  return f;
}

constexpr std::uint32_t kInput = 0x100;                  // WheelSlip_0: rig to node
constexpr std::uint32_t kOutput = proto::kNodeStatusId;  // node to rig

TEST(LogReplay, InputsUpToACycleTimeComeBeforeItsComputation) {
  FakeNode node;
  Sink sink;
  LogReplay replay(node, sink, 1'000'000);
  // Classic log order: inputs, the node's frames of the cycle, then an input logged at the same
  // microsecond after them; a cycle of two output frames; a gap of three periods.
  const std::vector<std::pair<std::uint32_t, std::int64_t>> log = {
      {kInput, 1'000'000}, {kOutput, 1'000'000}, {kInput, 1'000'000},
      {kInput, 2'000'000}, {kOutput, 2'000'000}, {0x180, 2'000'000},
      {kInput, 5'000'000}, {kOutput, 5'000'000}, {kInput, 5'500'000}};
  for (const auto& [id, t] : log) {
    ASSERT_EQ(replay.add(frame(id), t), Status::ok);
  }
  replay.finish();
  const std::vector<std::string> expected = {"rx 256@1000000", "rx 256@1000000",  "compute@1000000",
                                             "rx 256@2000000", "compute@2000000", "rx 256@5000000",
                                             "overrun 2",      "compute@5000000", "rx 256@5500000"};
  EXPECT_EQ(node.calls, expected);
  EXPECT_EQ(replay.counts().cycles, 3U);
  EXPECT_EQ(replay.counts().overruns, 2U);
  EXPECT_EQ(replay.counts().input_frames, 5U);
  EXPECT_EQ(replay.counts().logged_tx_frames, 4U);
  EXPECT_EQ(replay.counts().tx_frames, 3U);
  EXPECT_EQ(sink.sent, (std::vector<std::int64_t>{1'000'000, 2'000'000, 5'000'000}));
  EXPECT_EQ(sink.logged.size(), 4U);
}

TEST(LogReplay, SyncModeReportsNoOverruns) {
  FakeNode node;
  node.cfg.schedule = Schedule::sync;
  Sink sink;
  LogReplay replay(node, sink, 1'000'000);
  ASSERT_EQ(replay.add(frame(kOutput), 1'000'000), Status::ok);
  ASSERT_EQ(replay.add(frame(kOutput), 9'000'000), Status::ok);
  replay.finish();
  EXPECT_EQ(replay.counts().overruns, 0U);
  EXPECT_EQ(replay.counts().cycles, 2U);
}

TEST(LogReplay, RefusesAFrameEarlierThanTheOneBefore) {
  FakeNode node;
  Sink sink;
  LogReplay replay(node, sink, 1'000'000);
  ASSERT_EQ(replay.add(frame(kInput), 2'000'000), Status::ok);
  EXPECT_EQ(replay.add(frame(kInput), 1'999'000), Status::out_of_range);
  EXPECT_EQ(node.calls.size(), 1U);  // the refused frame was not received
}

}  // namespace
}  // namespace tread::node
