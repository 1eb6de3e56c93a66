// The Magic Formula on four float lanes: packs four wheels' inputs, evaluates once, unpacks.
// On x86-64 the evaluation is compiled three times (x86-64-v4 with AVX-512 broadcasts, v3 with
// AVX2/FMA, the SSE2 baseline) and the loader picks the best the CPU has (GCC target_clones).
// The v3 and v4 clones contract a·b + c into FMA instructions (as any aarch64 build does) and
// agree bit for bit (checked under qemu -cpu Haswell against this AVX-512 machine); the baseline
// clone's results differ from theirs in the last bits.
#include "mf/mf_evaluate_four.hpp"

#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>

#include "mf/mf_lane_transpose.hpp"
#include "mf/mf_lanes.hpp"

namespace tread::mf {

namespace {

using lanes::F4;
using lanes::V;

// MfInput and MfOutput are runs of floats (MfOutput: then its status): packing and unpacking
// transpose four of them at a time.
constexpr std::size_t kInputFields = sizeof(MfInput<float>) / sizeof(float);
constexpr std::size_t kOutputFields = offsetof(MfOutput<float>, status) / sizeof(float);
static_assert(std::is_standard_layout_v<MfInput<float>> && kInputFields == 7);
static_assert(offsetof(MfInput<float>, fz_n) == 0 * sizeof(float) &&
              offsetof(MfInput<float>, kappa) == 1 * sizeof(float) &&
              offsetof(MfInput<float>, alpha_rad) == 2 * sizeof(float) &&
              offsetof(MfInput<float>, gamma_rad) == 3 * sizeof(float) &&
              offsetof(MfInput<float>, vx_mps) == 4 * sizeof(float) &&
              offsetof(MfInput<float>, phit_1pm) == 5 * sizeof(float) &&
              offsetof(MfInput<float>, p_pa) == 6 * sizeof(float));
static_assert(std::is_standard_layout_v<MfOutput<float>> &&
              std::is_standard_layout_v<MfOutput<F4>>);
static_assert(offsetof(MfOutput<F4>, status) == kOutputFields * sizeof(F4));
static_assert(offsetof(MfOutput<float>, kxk_n) == (kOutputFields - 1) * sizeof(float));

/// Four consecutive floats of each wheel's struct, from float `field` on.
template <typename S>
void load_rows(const std::array<S, 4>& wheels, std::size_t field, V (&rows)[4]) {
  for (std::size_t i = 0; i < 4; ++i) {
    std::memcpy(&rows[i], reinterpret_cast<const char*>(&wheels[i]) + field * sizeof(float),
                sizeof(V));
  }
}

// One function with everything inlined (the scheduler interleaves the independent chains), cloned
// per x86-64 level where GCC can.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TREAD_LANES_FUNCTION \
  __attribute__((flatten, target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define TREAD_LANES_FUNCTION __attribute__((flatten))
#endif

}  // namespace

TREAD_LANES_FUNCTION void evaluate_four(const MfParameters<float>& params,
                                        const std::array<MfInput<float>, 4>& inputs,
                                        const MfOptions& options,
                                        const std::array<MountedSide, 4>& sides,
                                        MfOutput<F4>& out) noexcept {
  // Mirroring per wheel: y → −y on the way in and out of its lane.
  lanes::Mask4 mirror;
  for (std::size_t i = 0; i < 4; ++i) {
    mirror.m[i] = mirrored(sides[i], params.tyre_side) ? -1 : 0;
  }
  // Inputs: floats 0–3 and 3–6 of each wheel, transposed.
  V rows[4];
  V columns[4];
  MfInput<F4> in;
  load_rows(inputs, 0, rows);
  lanes::transpose<4>(rows, columns);
  in.fz_n = F4(columns[0]);
  in.kappa = F4(columns[1]);
  in.alpha_rad = F4(columns[2]);
  load_rows(inputs, 3, rows);
  lanes::transpose<4>(rows, columns);
  in.gamma_rad = F4(columns[0]);
  in.vx_mps = F4(columns[1]);
  in.phit_1pm = F4(columns[2]);
  in.p_pa = F4(columns[3]);

  MfOptions lane_options = options;
  lane_options.side = MountedSide::as_measured;
  // Built in place (a prvalue initializing `out` directly), not assigned: assignment copied the
  // 480-byte result from evaluate's return slot, about 2 % of an evaluation. MfOutput<F4> is
  // trivially destructible, so ending the old object's lifetime this way needs no destructor call.
  static_assert(std::is_trivially_destructible_v<MfOutput<F4>>);
  ::new (static_cast<void*>(&out))
      MfOutput<F4>(evaluate(params, detail::mirror_input(in, mirror), lane_options));
  detail::mirror_output(out, mirror);
}

void evaluate_four(const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
                   const MfOptions& options, const std::array<MountedSide, 4>& sides,
                   std::array<MfOutput<float>, 4>& outputs) noexcept {
  MfOutput<F4> out;
  evaluate_four(params, inputs, options, sides, out);
  // Four fields at a time, transposed into each wheel's struct; the last one lane by lane.
  V fields[kOutputFields];
  std::memcpy(&fields, &out, sizeof(fields));
  V columns[4];
  std::size_t f = 0;
  for (; f + 4 <= kOutputFields; f += 4) {
    const V group[4] = {fields[f], fields[f + 1], fields[f + 2], fields[f + 3]};
    lanes::transpose<4>(group, columns);
    for (std::size_t i = 0; i < 4; ++i) {
      std::memcpy(reinterpret_cast<char*>(&outputs[i]) + f * sizeof(float), &columns[i], sizeof(V));
    }
  }
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t g = f; g < kOutputFields; ++g) {
      std::memcpy(reinterpret_cast<char*>(&outputs[i]) + g * sizeof(float),
                  reinterpret_cast<const char*>(&fields[g]) + i * sizeof(float), sizeof(float));
    }
    outputs[i].status = out.status[static_cast<int>(i)];
  }
}

}  // namespace tread::mf
