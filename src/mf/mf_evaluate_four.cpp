// The Magic Formula on four float lanes: packs four wheels' inputs, evaluates once, unpacks.
// On x86-64 the evaluation is compiled three times and the best the CPU has runs: x86-64-v4
// (AVX-512) in a file of its own (mf_evaluate_four_v4.cpp, where the selects differ), x86-64-v3
// (AVX2/FMA) and the SSE2 baseline here as GCC target_clones, which the loader picks between.
// The v3 and v4 code contract a·b + c into FMA instructions (as any aarch64 build does) and agree
// bit for bit (MfEvaluateFour.X8664V4EqualsV3BitForBit, on an AVX-512 CPU); the baseline clone's
// results differ from theirs in the last bits.
#include "mf/mf_evaluate_four.hpp"

#include <cstddef>
#include <cstring>
#include <type_traits>

#include "mf/mf_evaluate_four_lanes.hpp"
#include "mf/mf_lane_transpose.hpp"
#include "mf/mf_lanes.hpp"

namespace tread::mf {

namespace {

using lanes::F4;
using lanes::V;

// MfOutput is a run of floats, then its status: unpacking transposes four of them at a time.
constexpr std::size_t kOutputFields = offsetof(MfOutput<float>, status) / sizeof(float);
static_assert(std::is_standard_layout_v<MfOutput<float>> &&
              std::is_standard_layout_v<MfOutput<F4>>);
static_assert(offsetof(MfOutput<F4>, status) == kOutputFields * sizeof(F4));
static_assert(offsetof(MfOutput<float>, kxk_n) == (kOutputFields - 1) * sizeof(float));

// One function with everything inlined (the scheduler interleaves the independent chains), cloned
// per x86-64 level where GCC can.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TREAD_LANES_FUNCTION __attribute__((flatten, target_clones("arch=x86-64-v3", "default")))
#else
#define TREAD_LANES_FUNCTION __attribute__((flatten))
#endif

TREAD_LANES_FUNCTION void evaluate_four_cloned(const MfParameters<float>& params,
                                               const std::array<MfInput<float>, 4>& inputs,
                                               const MfOptions& options,
                                               const std::array<MountedSide, 4>& sides,
                                               MfOutput<F4>& out) noexcept {
  TREAD_EVALUATE_FOUR_BODY(params, inputs, options, sides, out);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// Everything evaluate_four_v4 is compiled for (x86-64-v4: AVX-512 F/BW/CD/DQ/VL and all of v3).
/// __builtin_cpu_init first: a call from a static initializer may come before libgcc's own.
bool four_lanes_v4() noexcept {
  static const bool v4 = (__builtin_cpu_init(), __builtin_cpu_supports("x86-64-v4"));
  return v4;
}
#endif

}  // namespace

void evaluate_four(const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
                   const MfOptions& options, const std::array<MountedSide, 4>& sides,
                   MfOutput<F4>& out) noexcept {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  if (four_lanes_v4()) {
    four::evaluate_four_v4(params, inputs, options, sides, out);
    return;
  }
#endif
  evaluate_four_cloned(params, inputs, options, sides, out);
}

void detail::evaluate_four_without_v4(const MfParameters<float>& params,
                                      const std::array<MfInput<float>, 4>& inputs,
                                      const MfOptions& options,
                                      const std::array<MountedSide, 4>& sides,
                                      MfOutput<F4>& out) noexcept {
  evaluate_four_cloned(params, inputs, options, sides, out);
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
