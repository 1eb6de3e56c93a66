#include "timing_benchmarks.hpp"

#include <cstdint>
#include <string_view>
#include <type_traits>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "node_path.hpp"
#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"
#include "proto/messages.hpp"
#include "semihost/semihost.hpp"
#include "text_line.hpp"

namespace tread::firmware {
namespace {

using S = node::ChannelScalar<TyreChannel>;  // float, or fixed::Fixed64 on the integer-only image

// Keep the results observable.
volatile float g_float_sink;
volatile std::int64_t g_sink;

template <typename T>
void sink(T value) noexcept {
  if constexpr (std::is_same_v<T, float>) {
    g_float_sink = value;
  } else {
    g_sink = value.raw();
  }
}

/// first + step × i in the image's scalar (an integer product in fixed point).
template <typename T>
T grid(T first, T step, std::uint32_t i) noexcept {
  if constexpr (std::is_same_v<T, float>) {
    return first + step * static_cast<float>(i);
  } else {
    return first + step * T::from_raw(static_cast<std::int64_t>(i) << T::kFractionBits);
  }
}

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

void run_timing_benchmarks(hal::SysTickCounter& counter) noexcept {
  constexpr std::uint32_t kLoop = 100'000;
  report("calibration_2x100000_instructions", 1, calibration(counter, kLoop));

  // Magic Formula: 16 × 16 slips at 4 kN, 16.7 m/s, 1° camber, as the node's channels call it.
  mf::MfOptions o = tyre_options();
  o.extras = true;
  o.extras_loaded_radius_only = true;
  constexpr std::uint32_t kGrid = 16;
  std::uint32_t start = counter.ticks();
  for (std::uint32_t i = 0; i < kGrid; ++i) {
    for (std::uint32_t j = 0; j < kGrid; ++j) {
      mf::MfInput<S> in;
      in.fz_n = S(4000.0);
      in.vx_mps = S(16.7);
      in.gamma_rad = S(0.0175);
      in.kappa = grid(S(-0.2), S(0.025), i);
      in.alpha_rad = grid(S(-0.15), S(0.02), j);
      const mf::MfOutput<S> out = mf::evaluate(kTyreParameters, in, o);
      sink(out.fx_n + out.fy_n + out.mz_nm + out.rl_m);
    }
  }
  report("mf_evaluate", kGrid * kGrid, counter.ticks() - start);

  // Contact lookup through the node's channel, 1024 displacements over ±12.8 mm.
  const ContactChannel channel(contact_table());
  constexpr std::uint32_t kLookups = 1024;
  start = counter.ticks();
  for (std::uint32_t k = 0; k < kLookups; ++k) {
    proto::BasicWheelsetInput<S> in;
    in.lateral_mm = grid(S(-12.8), S(0.025), k);
    const node::BasicContactResult<S> r = channel.evaluate(in);
    sink(r.delta_r_mm + r.gamma_left_rad);
  }
  report("contact_lookup", kLookups, counter.ticks() - start);

  // Encoding the node's outputs (classic CAN: every node-to-rig frame, with E2E protection), as
  // compute() ends each cycle.
  proto::BasicNodeData<S> outputs;
  for (auto& w : outputs.wheels) {
    w = proto::BasicWheelOutput<S>{S(-2345.6), S(1234.5), S(-45.6), S(12.3),
                                   S(-23.4),   S(0.3456), 0};
  }
  for (auto& ws : outputs.wheelsets) {
    ws = proto::BasicWheelsetOutput<S>{S(460.1), S(459.9), S(0.2), S(0.025), S(-0.025), 0};
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
      g_sink = frame.data[0];
      ++frames;
    }
  }
  report("encode_frame", frames, counter.ticks() - start);
}

}  // namespace tread::firmware
