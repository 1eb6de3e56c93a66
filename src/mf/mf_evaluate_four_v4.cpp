// evaluate_four for x86-64-v4 (AVX-512 F/BW/CD/DQ/VL), in a file of its own compiled for that
// level as a whole (-march=x86-64-v4, src/mf/CMakeLists.txt): __AVX512VL__ is defined here, so
// lanes::if_else selects bit by bit, one vpternlogd, instead of by vblendvps (see there why),
// which a GCC target_clones clone of the baseline file cannot tell apart. On the Intel VM (a
// Sapphire Rapids Xeon), two alternating mf_bench runs: four lanes' MF 6.1 414–419 → 373–374 ns
// and MF 6.2 559–567 → 499 ns per group of four. The bits are those of the x86-64-v3 clone
// (MfEvaluateFour.X8664V4EqualsV3BitForBit) and of the 16-lane batch
// (MfEvaluateBatch.EqualsEvaluateFour).
//
// Nothing compiled here may run on a CPU below x86-64-v4, so nothing here may be shared with
// baseline code: the one function defined here inlines everything it calls (flatten) but the rare
// lanes::redo_lanes, which has internal linkage; tests/mf/wide_object_symbols.sh checks that this
// object defines no symbol another object could bind to but evaluate_four_v4.
#include "mf/mf_evaluate_four_lanes.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#if !defined(__AVX512F__) || !defined(__AVX512BW__) || !defined(__AVX512CD__) || \
    !defined(__AVX512DQ__) || !defined(__AVX512VL__) || !defined(__FMA__)
#error "mf_evaluate_four_v4.cpp must be compiled with -march=x86-64-v4 (src/mf/CMakeLists.txt)"
#endif

namespace tread::mf::four {

__attribute__((flatten)) void evaluate_four_v4(const MfParameters<float>& params,
                                               const std::array<MfInput<float>, 4>& inputs,
                                               const MfOptions& options,
                                               const std::array<MountedSide, 4>& sides,
                                               MfOutput<lanes::F4>& out) noexcept {
  TREAD_EVALUATE_FOUR_BODY(params, inputs, options, sides, out);
}

}  // namespace tread::mf::four
#endif
