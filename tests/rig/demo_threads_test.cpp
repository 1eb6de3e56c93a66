// The HIL demo on the real clock: the node on its own thread, the rig on another, joined by the
// lock-free in-process link. These tests assert what the run promises whatever the machine's
// timing (they do not need SCHED_FIFO and do not measure speed): sync mode is lockstep and gives
// the simulated clock's trace value for value; periodic mode accounts for every cycle and every
// answer it checks matches the reference; the log written through the lock-free ring is complete
// and replays bit for bit.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>

#include "demo_run.hpp"
#include "rig/hil_demo.hpp"
#include "runtime/candump_log.hpp"
#include "runtime/node_session.hpp"

namespace tread::host {
namespace {

using testing::demo_settings;

/// "" when the two files are equal, else the first line that differs.
std::string first_difference(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::ifstream fa(a);
  std::ifstream fb(b);
  std::string la;
  std::string lb;
  for (int line = 1;; ++line) {
    const bool ga = static_cast<bool>(std::getline(fa, la));
    const bool gb = static_cast<bool>(std::getline(fb, lb));
    if (!ga && !gb) {
      return "";
    }
    if (ga != gb || la != lb) {
      return "line " + std::to_string(line) + ": '" + la + "' vs '" + lb + "'";
    }
  }
}

TEST(DemoThreads, SyncModeIsLockstepAndGivesTheSimulatedClocksTrace) {
  DemoSettings sim = demo_settings({"sweep", "step-steer"}, "threads_sync_sim");
  sim.sweep_duration_s = 0.5;
  DemoSettings rt = sim;
  rt.out_dir = testing::rig_test_dir("threads_sync_rt");
  rt.sim_clock = false;
  rt.node.node.schedule = node::Schedule::sync;
  // An input timeout longer than any hold-up of the rig: the node computes only on the rig's cycle
  // frames, never on its own between them (as `tread rig` asks of a node in sync mode).
  rt.node.node.input_timeout_ns = 600'000'000'000;

  const DemoResult a = run_demo(sim);
  const DemoResult b = run_demo(rt);
  ASSERT_TRUE(b.threaded);
  ASSERT_EQ(a.scenarios.size(), 2U);
  ASSERT_EQ(b.scenarios.size(), 2U);
  std::uint64_t cycles = 0;
  for (std::size_t i = 0; i < a.scenarios.size(); ++i) {
    EXPECT_EQ(a.scenarios[i].cycles, b.scenarios[i].cycles);
    EXPECT_EQ(first_difference(a.scenarios[i].trace_csv, b.scenarios[i].trace_csv), "")
        << a.scenarios[i].name;
    cycles += b.scenarios[i].cycles;
  }
  EXPECT_EQ(b.unanswered_cycles, 0U);
  EXPECT_EQ(b.answers.unchecked_cycles, 0U);
  EXPECT_EQ(b.answers.answers_checked, a.answers.answers_checked);
  EXPECT_EQ(b.answer_latency.count(), cycles);  // a CAN-in → CAN-out figure for every cycle
  EXPECT_EQ(b.report.counters.rx_rejected(), 0U);
  EXPECT_EQ(b.rig_frames_rejected, 0U);
}

TEST(DemoThreads, PeriodicModeAccountsForEveryCycleAndEveryCheckedAnswerMatches) {
  DemoSettings s = demo_settings({"sweep"}, "threads_periodic");
  s.sweep_duration_s = 1.0;
  s.sim_clock = false;
  s.log = s.out_dir / "node.log";
  // As a rig runs it, where the system grants it (root): the node at SCHED_FIFO on the last CPU,
  // the rig below it on another. Refused, the run is the same, only less punctual.
  s.realtime.fifo_priority = 80;
  s.realtime.cpu = static_cast<int>(std::thread::hardware_concurrency()) - 1;
  const DemoResult r = run_demo(s);
  ASSERT_TRUE(r.threaded);
  ASSERT_EQ(r.scenarios.size(), 1U);
  const std::uint64_t cycles = r.scenarios[0].cycles;
  EXPECT_EQ(cycles, 1000U);
  // Every rig cycle either got its answer within its window (and has a latency figure) or did not.
  EXPECT_EQ(r.answer_latency.count() + r.unanswered_cycles, cycles);
  // Unchecked: the late inputs and the missing answers (a cycle can be both).
  EXPECT_LE(r.answers.unchecked_cycles, r.late_sends + r.unanswered_cycles);
  EXPECT_GE(r.answers.unchecked_cycles, std::max(r.late_sends, r.unanswered_cycles));
  // The node's own grid: every deadline of the rig's cycles was computed or counted as missed.
  EXPECT_GE(r.report.loop.cycles + r.report.loop.overruns, cycles);
  EXPECT_EQ(r.report.counters.rx_rejected(), 0U);
  // The answers checked match as in the simulated run (0.5 N force steps, 1 µm Δr steps). The rig
  // takes as cycle k's answer one whose status left the node at or after deadline k. An answer of
  // an earlier deadline could pass that only if the node spent more than the rig's lead (half a
  // period, less the sending) between its wake-up and its status frame: a cycle time the node's
  // own histogram shows. On a machine that held the node up that long the check is not promised.
  EXPECT_GT(r.answers.answers_checked, 0U);
  const std::int64_t lead_ns = s.period_us * 1000 / 2 - 100'000;
  if (r.report.loop.cycle_time.max_ns() < lead_ns) {
    EXPECT_LE(r.answers.max_force_error_n, 0.6);
    EXPECT_LE(r.answers.max_moment_error_nm, 0.03);
    EXPECT_LE(r.answers.max_delta_r_error_mm, 0.00051);
  } else {
    std::cout << "the node's longest cycle took " << r.report.loop.cycle_time.max_ns() / 1000
              << " us: answers not compared\n";
  }

  // The node's log went through the lock-free ring to the writer thread: whole, and a replay of it
  // reproduces every frame the node sent.
  EXPECT_EQ(r.log_records_dropped, 0U);
  ASSERT_EQ(r.report.log_error, "");
  const ReplayResult replay = run_replay(s.node, s.log, s.period_us, {});
  EXPECT_TRUE(replay.identical) << replay.first_difference;
  EXPECT_EQ(replay.report.loop.cycles, r.report.loop.cycles);
}

/// `tread node --can CAN --log OUT_DIR/LOG` for `cycles` cycles.
LiveOptions live_options(const DemoSettings& s, const std::string& can, std::uint64_t cycles,
                         const char* log) {
  LiveOptions live;
  live.can = can;
  live.cycles = cycles;
  live.log = s.out_dir / log;
  return live;
}

// `tread node --log` live: the loop's frames go through the same ring to the writer thread (no I/O
// on the loop's thread); the log is whole, one NodeStatus per cycle, each line candump's.
TEST(LiveNode, LogThroughTheRingIsWhole) {
  const DemoSettings s = demo_settings({"sweep"}, "live_node_log");
  const LiveOptions live = live_options(s, "stub", 200, "live.log");
  const SessionReport report = run_live(s.node, live, nullptr);
  ASSERT_EQ(report.log_error, "");
  ASSERT_EQ(report.loop.cycles, 200U);
  std::ifstream in(live.log);
  std::string line;
  std::uint64_t lines = 0;
  std::uint64_t statuses = 0;
  while (std::getline(in, line)) {
    ++lines;
    ASSERT_EQ(line.rfind("(", 0), 0U) << line;
    ASSERT_NE(line.find(") stub "), std::string::npos) << line;
    statuses += line.find(" stub 0F0#") != std::string::npos ? 1U : 0U;
  }
  EXPECT_EQ(statuses, report.loop.cycles);
  EXPECT_GT(lines, statuses);
}

// A bus that cannot be opened stops the live node before its log is opened: no log, complete,
// incomplete or partial, is left behind (the log is opened between the bus and the real-time
// settings).
TEST(LiveNode, AnUnopenableBusLeavesNoLog) {
  const DemoSettings s = demo_settings({"sweep"}, "live_node_no_bus");
  const std::string can = "tread_nocan0";  // a valid interface name (≤ 15 characters), absent
  const LiveOptions live = live_options(s, can, 10, "never.log");
  for (const char* suffix : {"", ".incomplete", ".partial"}) {
    std::filesystem::remove(live.log.string() + suffix);
  }
  try {
    static_cast<void>(run_live(s.node, live, nullptr));
    ADD_FAILURE() << "the node ran without its bus";
  } catch (const std::runtime_error& e) {
    // Without SocketCAN (the host) the error says so; with it (the VM) it names the interface.
    const std::string what = e.what();
    EXPECT_TRUE(what.find(can) != std::string::npos || what.find("SocketCAN") != std::string::npos)
        << what;
  }
  for (const char* suffix : {"", ".incomplete", ".partial"}) {
    EXPECT_FALSE(std::filesystem::exists(live.log.string() + suffix)) << suffix;
  }
}

// A log whose frames did not all reach the writer (a full ring) never gets its name: it is kept as
// `<path>.incomplete` and finish() says how many were lost; with none lost it is the log.
TEST(CandumpWriter, DroppedFramesKeepTheLogIncomplete) {
  const std::filesystem::path dir = testing::rig_test_dir("candump_dropped");
  proto::CanFrame frame{};
  frame.id = 0x0F0;
  frame.len = 1;
  for (const std::uint64_t dropped : {std::uint64_t{0}, std::uint64_t{2}}) {
    const std::filesystem::path log = dir / ("run_" + std::to_string(dropped) + ".log");
    const std::filesystem::path kept(log.string() + ".incomplete");
    std::filesystem::remove(log);
    std::filesystem::remove(kept);
    CandumpWriter writer;
    writer.open(log, "vcan0");
    for (int i = 0; i < 3; ++i) writer.write(frame, 1'000'000 * i);
    const std::string error = writer.finish(dropped);
    if (dropped == 0) {
      EXPECT_EQ(error, "");
      EXPECT_TRUE(std::filesystem::exists(log));
      EXPECT_FALSE(std::filesystem::exists(kept));
    } else {
      EXPECT_NE(error.find("2 frames were not logged"), std::string::npos) << error;
      EXPECT_NE(error.find(kept.string()), std::string::npos) << error;
      EXPECT_FALSE(std::filesystem::exists(log));
      ASSERT_TRUE(std::filesystem::exists(kept));
      EXPECT_EQ(read_candump_log(kept).size(), 3U);
    }
  }
  // A later run under the same name that is whole leaves no older run's .incomplete beside it.
  const std::filesystem::path log = dir / "run_2.log";
  CandumpWriter again;
  again.open(log, "vcan0");
  again.write(frame, 0);
  EXPECT_EQ(again.finish(), "");
  EXPECT_TRUE(std::filesystem::exists(log));
  EXPECT_FALSE(std::filesystem::exists(log.string() + ".incomplete"));
}

}  // namespace
}  // namespace tread::host
