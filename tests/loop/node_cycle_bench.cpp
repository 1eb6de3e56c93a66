// Full cycle compute time of the node (not pass/fail): receive the rig's frames of one cycle (E2E
// check, decode), compute 4 tyres (MF 6.1 float, combined, with Rl) and 2 wheelsets (contact
// table), encode and protect every output frame. Target ≤ 2 µs per cycle. The HAL is not involved.
#include <benchmark/benchmark.h>

#include <time.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>

#include "golden_path.hpp"
#include "lut/tread_lut.hpp"
#include "node/contact_table_channel.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/node.hpp"
#include "proto/rig_link.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

using namespace tread;

/// Sleeps until the next whole millisecond of CLOCK_MONOTONIC, as the loop sleeps to its deadline.
void sleep_to_next_ms() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const std::int64_t ns = static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
  const std::int64_t next = (ns / 1'000'000 + 1) * 1'000'000;
  const timespec at{static_cast<time_t>(next / 1'000'000'000),
                    static_cast<long>(next % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &at, nullptr) == EINTR) {
  }
}

/// `after_sleep`: each cycle after a sleep to the next millisecond, timed alone (manual time), as
/// the loop meets it: the caches and TLB as the sleep left them, where back-to-back cycles find
/// them warm.
template <typename Tyre>
void run_cycles(benchmark::State& state, std::array<Tyre, 4>& tyres, bool after_sleep = false) {
  const auto layout = state.range(0) == 0 ? proto::Layout::classic : proto::Layout::fd;
  std::array<node::ContactTableChannel, 2> contacts;
  for (auto& c : contacts) c = node::ContactTableChannel(lut::contact_pairs()[0].f32);
  node::Node<Tyre, node::ContactTableChannel> n(
      node::NodeConfig{layout, 4, 2, 10'000'000, node::Schedule::periodic, true, 3}, tyres,
      contacts);
  proto::RigLink rig(layout, 4, 2);
  // 60 prepared cycles of rig frames with varying slips (counters in sequence).
  constexpr std::size_t kCycles = 60;  // a multiple of 15: the E2E counters continue in sequence
  std::array<std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames>, kCycles> frames{};
  std::array<std::size_t, kCycles> counts{};
  for (std::size_t c = 0; c < kCycles; ++c) {
    proto::RigData d;
    const float s = static_cast<float>(c) / kCycles;
    for (auto& w : d.wheels)
      w = {0.2F * s - 0.1F, 0.15F * s - 0.07F, 0.01F, 3000.0F + 2000.0F * s, 16.7F, 0.0F, false};
    for (auto& ws : d.wheelsets) ws = {10.0F * s - 5.0F, 0.0F, false};
    counts[c] = rig.encode_cycle(d, frames[c]);
  }
  std::array<proto::CanFrame, node::kMaxTxFrames> tx{};
  std::int64_t now = 0;
  std::size_t c = 0;
  for (auto _ : state) {
    std::chrono::steady_clock::time_point start{};
    if (after_sleep) {
      sleep_to_next_ms();
      start = std::chrono::steady_clock::now();
    }
    now += 1'000'000;
    for (std::size_t k = 0; k < counts[c]; ++k) {
      benchmark::DoNotOptimize(n.receive(frames[c][k], now));
    }
    benchmark::DoNotOptimize(n.compute(now, tx));
    c = (c + 1) % kCycles;
    if (after_sleep) {
      state.SetIterationTime(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  }
  state.counters["rejected"] = static_cast<double>(n.counters().rx_rejected());
  state.SetLabel(layout == proto::Layout::classic ? "classic: 11 rx + 13 tx frames"
                                                  : "FD: 1 rx + 3 tx frames");
}

/// The full cycle with MF 6.1 (float, combined, with Rl) on four wheels.
void BM_NodeCycle(benchmark::State& state) {
  const mf::MfParameters<float> params = mf::convert_parameters<float>(
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params);
  std::array<node::MfTyreChannel, 4> tyres;
  for (auto& t : tyres) t = node::MfTyreChannel(params, mf::MfOptions{});
  run_cycles(state, tyres);
}
BENCHMARK(BM_NodeCycle)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

/// The same cycle, each after a sleep to the next millisecond (classic layout): what the loop's
/// cycle time meets on a machine whose caches the sleep leaves cold (a VM's idle vCPU, another
/// task on the CPU).
void BM_NodeCycleAfterSleep(benchmark::State& state) {
  const mf::MfParameters<float> params = mf::convert_parameters<float>(
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params);
  std::array<node::MfTyreChannel, 4> tyres;
  for (auto& t : tyres) t = node::MfTyreChannel(params, mf::MfOptions{});
  run_cycles(state, tyres, true);
}
BENCHMARK(BM_NodeCycleAfterSleep)
    ->Arg(0)
    ->UseManualTime()
    ->Iterations(2000)
    ->Unit(benchmark::kNanosecond);

/// The same cycle without the tyre model: the node's own cost (E2E, codec, contact tables).
void BM_NodeCycleWithoutTyreModel(benchmark::State& state) {
  std::array<node::NoTyre, 4> tyres{};
  run_cycles(state, tyres);
}
BENCHMARK(BM_NodeCycleWithoutTyreModel)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
