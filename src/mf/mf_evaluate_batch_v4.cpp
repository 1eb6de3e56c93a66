// The 16-lane batch for x86-64-v4 (AVX-512 F/BW/CD/DQ/VL), in a file of its own that is compiled
// for that level as a whole (-march=x86-64-v4, src/mf/CMakeLists.txt), as the 8-lane AVX2 batch is
// (mf_evaluate_batch_v3.cpp): with a target attribute on a function of the baseline file, the
// aggregates of 16-lane vectors (Lanes<16>, Mask<16> and the evaluation's structs that hold them)
// were laid out for the baseline target, which has no 64-byte vector registers.
//
// Nothing compiled here may run on a CPU below x86-64-v4, so nothing here may be shared with
// baseline code: the one function defined here inlines everything it calls (flatten) but the rare
// lanes::redo_lanes, which has internal linkage (this file's own copy); tests/mf/
// wide_object_symbols.sh checks that this object defines no symbol another object could bind to
// but evaluate_sixteen_v4. mf_evaluate_batch.cpp calls it only where the CPU is x86-64-v4.
#include "mf/mf_evaluate_blocks.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#if !defined(__AVX512F__) || !defined(__AVX512BW__) || !defined(__AVX512CD__) || \
    !defined(__AVX512DQ__) || !defined(__AVX512VL__) || !defined(__FMA__)
#error "mf_evaluate_batch_v4.cpp must be compiled with -march=x86-64-v4 (src/mf/CMakeLists.txt)"
#endif

namespace tread::mf::batch {

__attribute__((flatten)) void evaluate_sixteen_v4(const MfParameters<float>& params,
                                                  std::span<const MfInput<float>> inputs,
                                                  const MfOptions& options,
                                                  std::span<MfOutput<float>> outputs) noexcept {
  evaluate_blocks<16>(params, inputs, options, outputs);
}

}  // namespace tread::mf::batch
#endif
