// Batches on wide lanes (the blocks: mf_evaluate_blocks.hpp). On x86-64 (GCC) the 16-lane blocks
// are compiled for x86-64-v4 (AVX-512: evaluate_sixteen_v4, mf_evaluate_batch_v4.cpp) and the
// 8-lane blocks twice, for x86-64-v3 (AVX2, FMA: evaluate_eight_v3, mf_evaluate_batch_v3.cpp) and
// for the SSE2 baseline (evaluate_eight, here); each wide file is compiled for its level as a whole.
// The CPU's features choose at run time. As in mf_evaluate_four.cpp, the v3/v4 code contracts
// a·b + c into FMAs the same way at every width, so a wheel's results do not depend on the width or
// its lane.
// Elsewhere (4 lanes: NEON, or a clang build) a block is evaluate_four.
#include "mf/mf_evaluate_batch.hpp"

#include "mf/mf_evaluate_blocks.hpp"

namespace tread::mf {

namespace {

using batch::evaluate_blocks;

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TREAD_WIDE_LANES 1
/// The SSE2 baseline's 8 lanes (pairs of 4-lane registers), for x86-64 CPUs below x86-64-v3.
__attribute__((flatten)) void evaluate_eight(const MfParameters<float>& params,
                                             std::span<const MfInput<float>> inputs,
                                             const MfOptions& options,
                                             std::span<MfOutput<float>> outputs) {
  evaluate_blocks<8>(params, inputs, options, outputs);
}
/// Everything evaluate_sixteen_v4 is compiled for (x86-64-v4: AVX-512 F/BW/CD/DQ/VL and all of v3,
/// BMI2, MOVBE, ... included), not only the AVX-512 flags.
bool has_avx512() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v4");
}
/// Everything evaluate_eight_v3 is compiled for (x86-64-v3: AVX2, FMA, BMI1/2, F16C, MOVBE, ...).
bool has_v3() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3");
}
bool eight_lanes_v3() noexcept {
  static const bool v3 = has_v3();
  return v3;
}
#else
#define TREAD_WIDE_LANES 0
__attribute__((flatten)) void evaluate_four_lanes(const MfParameters<float>& params,
                                                  std::span<const MfInput<float>> inputs,
                                                  const MfOptions& options,
                                                  std::span<MfOutput<float>> outputs) {
  evaluate_blocks<4>(params, inputs, options, outputs);
}
#endif

}  // namespace

bool sixteen_lanes_available() noexcept {
#if TREAD_WIDE_LANES
  static const bool wide = has_avx512();
  return wide;
#else
  return false;
#endif
}

int batch_lanes() noexcept {
#if TREAD_WIDE_LANES
  return sixteen_lanes_available() ? 16 : 8;
#else
  return 4;
#endif
}

void evaluate_batch_on(int lanes, const MfParameters<float>& params,
                       std::span<const MfInput<float>> inputs, const MfOptions& options,
                       std::span<MfOutput<float>> outputs) noexcept {
#if TREAD_WIDE_LANES
  if (lanes == 16 && sixteen_lanes_available()) {
    batch::evaluate_sixteen_v4(params, inputs, options, outputs);
  } else if (eight_lanes_v3()) {
    batch::evaluate_eight_v3(params, inputs, options, outputs);
  } else {
    evaluate_eight(params, inputs, options, outputs);
  }
#else
  static_cast<void>(lanes);
  evaluate_four_lanes(params, inputs, options, outputs);
#endif
}

void evaluate_batch(const MfParameters<float>& params, std::span<const MfInput<float>> inputs,
                    const MfOptions& options, std::span<MfOutput<float>> outputs) noexcept {
  evaluate_batch_on(batch_lanes(), params, inputs, options, outputs);
}

}  // namespace tread::mf
