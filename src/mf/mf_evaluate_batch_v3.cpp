// The 8-lane batch for x86-64-v3 (AVX2, FMA), in a file of its own that is compiled for that level
// as a whole (-march=x86-64-v3, src/mf/CMakeLists.txt), where a target attribute (or GCC's
// target_clones) on a function of a baseline file gave slower code: there the aggregates of 8-lane
// vectors (Lanes<8>, Mask<8> and the structs of the evaluation that hold them) are laid out for the
// baseline target, which has no 32-byte vector registers, and more of them went through the stack.
// AVX2 VM (AMD EPYC), 8-lane batch, MF 6.1 with all outputs, callgrind: 4 235 → 4 009 instructions
// per block of eight, stack loads and stores 1 667 → 1 431; p10 of 2 000 alternating passes over four
// code placements: 75.0 → 68.4 ns per wheel (−9 %), MF 6.2 97.3 → 91.0 ns; the same bits.
//
// Nothing compiled here may run on a CPU below x86-64-v3, so nothing here may be shared with
// baseline code: the one function defined here inlines everything it calls (flatten) but the rare
// lanes::redo_lanes, which has internal linkage (this file's own copy); tests/mf/
// wide_object_symbols.sh checks that this object defines no symbol another object could bind to
// but evaluate_eight_v3. mf_evaluate_batch.cpp calls it only where the CPU is x86-64-v3.
#include "mf/mf_evaluate_blocks.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "mf_evaluate_batch_v3.cpp must be compiled with -march=x86-64-v3 (src/mf/CMakeLists.txt)"
#endif

namespace tread::mf::batch {

__attribute__((flatten)) void evaluate_eight_v3(const MfParameters<float>& params,
                                                std::span<const MfInput<float>> inputs,
                                                const MfOptions& options,
                                                std::span<MfOutput<float>> outputs) noexcept {
  evaluate_blocks<8>(params, inputs, options, outputs);
}

}  // namespace tread::mf::batch
#endif
