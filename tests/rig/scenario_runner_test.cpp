// The rig's side of a lockstep cycle (sim/rig/scenario_runner): which of the node's computations it
// takes as the answer to the cycle it has just sent. A node in sync mode also computes on its input
// timeout; such a computation can reach the rig while it waits for its answer (the rig was held up
// past the timeout and sent its first frames as the node's timeout came due). It must not be taken:
// the cycle's answer is the one whose NodeStatus names the rig cycle.

#include "rig/scenario_runner.hpp"

#include <gtest/gtest.h>

#include <array>
#include <span>
#include <vector>

#include "node/node.hpp"
#include "node/test_channels.hpp"
#include "rig/rig_session.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {
namespace {

constexpr std::int64_t kMs = 1'000'000;

/// One wheel driven at a fixed slip; records the answers the runner hands it.
class RecordingScenario final : public RigScenario {
 public:
  [[nodiscard]] std::string name() const override { return "recording"; }
  [[nodiscard]] std::string description() const override { return "records the answers"; }
  [[nodiscard]] double duration_s() const override { return 1.0; }
  void inputs(double /*t_s*/, proto::RigData& data) override {
    data.wheels[0] = proto::WheelInput{0.08F, 0.01F, 0.0F, 4000.0F, 20.0F, 60.0F, true};
  }
  void advance(const proto::RigData& /*inputs_seen*/, const proto::NodeData& answers,
               double /*dt_s*/) override {
    taken.push_back(answers.wheels[0]);
    statuses.push_back(answers.status);
  }
  [[nodiscard]] std::vector<std::string> trace_columns() const override { return {}; }
  void trace_values(std::vector<double>& /*row*/) const override {}
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override { return {}; }
  std::vector<std::filesystem::path> plot(const std::filesystem::path& /*trace_csv*/,
                                          const std::filesystem::path& /*out_dir*/) const override {
    return {};
  }

  std::vector<proto::WheelOutput> taken;
  std::vector<proto::NodeStatusData> statuses;
};

struct Lockstep {
  explicit Lockstep(proto::Layout layout, node::Schedule schedule)
      : config{layout, 1, 0, 10 * kMs, schedule, true, 3},
        node(config, tyres, contacts),
        link(layout, 1, 0),
        runner(scenario, link, layout, 1, 0, RigReference{}) {}

  /// The node receives `frames` and computes; the rig takes its frames. True when they completed
  /// the answer of the rig's cycle.
  bool node_answers(std::span<const proto::CanFrame> frames, std::int64_t now_ns) {
    for (const proto::CanFrame& f : frames) {
      static_cast<void>(node.receive(f, now_ns));
    }
    std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
    const std::size_t n = node.compute(now_ns, tx);
    bool complete = false;
    for (std::size_t k = 0; k < n; ++k) {
      complete = runner.on_frame(tx[k]);
      EXPECT_TRUE(k + 1 == n || !complete) << "completed before the computation's last frame";
    }
    return complete;
  }

  node::NodeConfig config;
  std::array<testing::LinearTyre, 1> tyres{};
  std::array<testing::LinearContact, 1> contacts{};
  node::Node<testing::LinearTyre, testing::LinearContact> node;
  proto::RigLink link;
  RecordingScenario scenario;
  ScenarioRunner runner;
};

class ScenarioRunnerLayout : public ::testing::TestWithParam<proto::Layout> {};

TEST_P(ScenarioRunnerLayout, TheNodesTimeoutComputationIsNotTakenAsTheCyclesAnswer) {
  Lockstep s(GetParam(), node::Schedule::sync);
  // Cycle 0. The node's input timeout comes due while the rig's first frames are on their way: it
  // computes without the cycle frame (stale: nothing reached it before), and that answer reaches
  // the rig after it has sent the whole cycle.
  const std::span<const proto::CanFrame> cycle0 = s.runner.begin_cycle(0.0, 0);
  ASSERT_GE(cycle0.size(), 1U);
  EXPECT_FALSE(s.node_answers(cycle0.first(cycle0.size() - 1), 1 * kMs));
  EXPECT_EQ(s.runner.check().other_answers, 1U);
  EXPECT_TRUE(s.node_answers(cycle0.last(1), 2 * kMs));  // the cycle frame: this cycle's answer
  s.runner.end_cycle(0.001, true);

  // Cycle 1: a timeout computation of the node after cycle 0 (its inputs still fresh) repeats
  // rig cycle 0, so it is not taken either, although nothing in it is stale.
  const std::span<const proto::CanFrame> cycle1 = s.runner.begin_cycle(0.001, 1);
  EXPECT_FALSE(s.node_answers({}, 3 * kMs));
  EXPECT_EQ(s.runner.check().other_answers, 2U);
  EXPECT_TRUE(s.node_answers(cycle1, 4 * kMs));
  s.runner.end_cycle(0.001, true);

  ASSERT_EQ(s.scenario.taken.size(), 2U);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(s.scenario.statuses[c].cycle, c);
    EXPECT_EQ(s.scenario.statuses[c].stale_mask, 0U) << c;
    EXPECT_EQ(s.scenario.taken[c].status, 0U) << c;
    EXPECT_NEAR(s.scenario.taken[c].fx_n, 80.0F, 0.5F) << c;    // 1000 κ Fz / 4000
    EXPECT_NEAR(s.scenario.taken[c].fy_n, -200.0F, 0.5F) << c;  // -20000 α
  }
  EXPECT_EQ(s.runner.check().unchecked_cycles, 0U);
  EXPECT_EQ(s.link.rejected(), 0U);  // the answers set aside still kept the E2E counters in step
}

TEST_P(ScenarioRunnerLayout, AComputationStraddlingTheCyclesStartIsNotTaken) {
  Lockstep s(GetParam(), node::Schedule::sync);
  const std::span<const proto::CanFrame> cycle0 = s.runner.begin_cycle(0.0, 0);
  EXPECT_TRUE(s.node_answers(cycle0, 1 * kMs));
  s.runner.end_cycle(0.001, true);
  // The node's timeout computation after cycle 0: its NodeStatus is drained between the cycles,
  // its other frames come after the rig has begun cycle 1 and the rig gives up on cycle 1 (no
  // answer): the scenario advances on cycle 0's answer, not on the timeout computation's frames.
  std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
  const std::size_t n = s.node.compute(50 * kMs, tx);  // 50 ms later: every channel stale
  ASSERT_GE(n, 2U);
  EXPECT_FALSE(s.runner.on_frame(tx[0]));  // between cycles: nothing is an answer
  EXPECT_EQ(s.runner.check().other_answers, 1U);
  static_cast<void>(s.runner.begin_cycle(0.001, 1));
  for (std::size_t k = 1; k < n; ++k) {
    EXPECT_FALSE(s.runner.on_frame(tx[k]));
  }
  s.runner.end_cycle(0.001, false);
  ASSERT_EQ(s.scenario.taken.size(), 2U);
  EXPECT_EQ(s.scenario.taken[1].status, 0U);  // cycle 0's answer, not the stale frames
  EXPECT_NEAR(s.scenario.taken[1].fx_n, 80.0F, 0.5F);
  EXPECT_EQ(s.runner.check().unchecked_cycles, 1U);
  EXPECT_EQ(s.link.rejected(), 0U);
}

TEST_P(ScenarioRunnerLayout, APeriodicNodesFirstComputationAfterTheCycleIsTheAnswer) {
  // In periodic mode NodeStatus.Cycle is the node's own count: the rig cannot tell and takes the
  // first complete computation (the demo's threaded rig orders them by time).
  Lockstep s(GetParam(), node::Schedule::periodic);
  const std::span<const proto::CanFrame> cycle0 = s.runner.begin_cycle(0.0, 0);
  EXPECT_TRUE(s.node_answers(cycle0, 1 * kMs));
  s.runner.end_cycle(0.001, true);
  EXPECT_EQ(s.runner.check().other_answers, 0U);
  ASSERT_EQ(s.scenario.taken.size(), 1U);
  EXPECT_NEAR(s.scenario.taken[0].fx_n, 80.0F, 0.5F);
}

INSTANTIATE_TEST_SUITE_P(Layouts, ScenarioRunnerLayout,
                         ::testing::Values(proto::Layout::classic, proto::Layout::fd),
                         [](const ::testing::TestParamInfo<proto::Layout>& p) {
                           return p.param == proto::Layout::classic ? "Classic" : "Fd";
                         });

// `tread rig`'s reference is the node's tyre as the node mounts it: --use-mode and --side reach the
// answer check and the vehicle scenarios' reference run (before, the rig always compared against
// the as-measured tyre at useMode 111).
TEST(RigScenarioContext, TakesTheNodesUseModeAndSide) {
  RigSettings s;
  s.tir = std::filesystem::path(TREAD_SOURCE_DIR) / "data/tyres/MagicFormula61_Parameters.tir";
  s.use_mode = 121;
  s.side = "left";
  const ScenarioContext c = rig_scenario_context(s);
  const mf::MfOptions want = node_tyre_options(121, "left");
  EXPECT_EQ(c.tyre_options.side, mf::MountedSide::left);
  EXPECT_EQ(c.tyre_options.side, want.side);
  EXPECT_EQ(c.tyre_options.use_alpha_star, want.use_alpha_star);
  EXPECT_TRUE(c.tyre_options.use_alpha_star);  // useMode x2x
  EXPECT_TRUE(c.tyre_options.extras);
  s.side = "up";
  EXPECT_THROW(static_cast<void>(rig_scenario_context(s)), std::runtime_error);
  s.side = "right";
  s.use_mode = 5;
  EXPECT_THROW(static_cast<void>(rig_scenario_context(s)), std::runtime_error);
}

}  // namespace
}  // namespace tread::host
