#include "timing_benchmarks.hpp"

#include <cstdint>
#include <string_view>

#include "mf/mf_evaluate.hpp"
#include "node/contact_table_channel.hpp"
#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"
#include "proto/messages.hpp"
#include "semihost/semihost.hpp"
#include "text_line.hpp"

namespace tread::firmware {
namespace {

volatile float g_sink;  // keeps the results observable

void report(std::string_view name, std::uint32_t calls, std::uint32_t ticks) noexcept {
  TextLine m;
  m << "timing " << name << ": " << std::uint64_t{calls} << " calls, " << std::uint64_t{ticks}
    << " ticks\n";
  hal::semihost::console(m.c_str());
}

/// `iterations` × (subs + bne): 2 instructions each, plus a few around the loop.
std::uint32_t calibration(hal::SysTickCounter& counter, std::uint32_t iterations) noexcept {
  const std::uint32_t start = counter.ticks();
  std::uint32_t n = iterations;
  __asm__ volatile(
      "1: subs %0, %0, #1\n\t"
      "bne 1b"
      : "+l"(n)
      :
      : "cc");
  return counter.ticks() - start;
}

}  // namespace

void run_timing_benchmarks(hal::SysTickCounter& counter, const mf::MfParameters<float>& tyre,
                           const mf::MfOptions& options,
                           const rail::ContactTableF32& table) noexcept {
  constexpr std::uint32_t kLoop = 100'000;
  report("calibration_2x100000_instructions", 1, calibration(counter, kLoop));

  // Magic Formula: 16 × 16 slips at 4 kN, 16.7 m/s, 1° camber, as the node's channels call it.
  mf::MfOptions o = options;
  o.extras = true;
  o.extras_loaded_radius_only = true;
  constexpr std::uint32_t kGrid = 16;
  std::uint32_t start = counter.ticks();
  for (std::uint32_t i = 0; i < kGrid; ++i) {
    for (std::uint32_t j = 0; j < kGrid; ++j) {
      mf::MfInput<float> in;
      in.fz_n = 4000.0F;
      in.vx_mps = 16.7F;
      in.gamma_rad = 0.0175F;
      in.kappa = -0.2F + 0.025F * static_cast<float>(i);
      in.alpha_rad = -0.15F + 0.02F * static_cast<float>(j);
      const mf::MfOutput<float> out = mf::evaluate(tyre, in, o);
      g_sink = out.fx_n + out.fy_n + out.mz_nm + out.rl_m;
    }
  }
  report("mf_evaluate", kGrid * kGrid, counter.ticks() - start);

  // Contact lookup through the node's channel, 1024 displacements over ±12.8 mm.
  const node::ContactTableChannel channel(table);
  constexpr std::uint32_t kLookups = 1024;
  start = counter.ticks();
  for (std::uint32_t k = 0; k < kLookups; ++k) {
    proto::WheelsetInput in;
    in.lateral_mm = -12.8F + 0.025F * static_cast<float>(k);
    const node::ContactResult r = channel.evaluate(in);
    g_sink = r.delta_r_mm + r.gamma_left_rad;
  }
  report("contact_lookup", kLookups, counter.ticks() - start);

  // Encoding the node's outputs (classic CAN: every node-to-rig frame, with E2E protection), as
  // compute() ends each cycle.
  proto::NodeData outputs;
  for (auto& w : outputs.wheels) {
    w = proto::WheelOutput{-2345.6F, 1234.5F, -45.6F, 12.3F, -23.4F, 0.3456F, 0};
  }
  for (auto& ws : outputs.wheelsets) {
    ws = proto::WheelsetOutput{460.1F, 459.9F, 0.2F, 0.025F, -0.025F, 0};
  }
  constexpr std::uint32_t kRounds = 16;
  std::uint32_t frames = 0;
  proto::CanFrame frame;
  start = counter.ticks();
  for (std::uint32_t r = 0; r < kRounds; ++r) {
    for (const proto::MessageSpec& m : proto::messages(proto::Layout::classic)) {
      if (m.direction != proto::Direction::node_to_rig) continue;
      static_cast<void>(proto::encode(
          m, outputs, static_cast<std::uint8_t>(r % proto::kE2eCounterModulo), frame));
      g_sink = static_cast<float>(frame.data[0]);
      ++frames;
    }
  }
  report("encode_frame", frames, counter.ticks() - start);
}

}  // namespace tread::firmware
