#pragma once
// Many wheels of one tyre at once, on wide float lanes: the Magic Formula (mf_evaluate.hpp)
// instantiated on 16 lanes where the CPU has AVX-512 (x86-64-v4), else 8 on x86-64 (AVX2 and FMA
// where the CPU has them, x86-64-v3; else SSE pairs) in GCC builds; 4 (NEON) on aarch64, 4 lanes
// of plain code elsewhere (and in clang builds). 8 and 16 lanes give the same bits. For offline work
// over millions of operating points (`tread mf eval --batch`, sweeps). Each wheel's results are
// those evaluate_four gives it on the same CPU, bit for bit and with the same status
// (tests/mf/mf_evaluate_batch_test.cpp), and do not depend on the batch's length or the wheel's
// place in it (bit for bit).

#include <cstddef>
#include <span>

#include "mf/mf_evaluate.hpp"

namespace tread::mf {

/// Evaluates inputs[i] into outputs[i] for every i (the spans have the same length) with the
/// same parameters and options (options.side: the mounted side of every wheel). Never allocates,
/// never throws; never returns NaN or inf (as evaluate).
void evaluate_batch(const MfParameters<float>& params, std::span<const MfInput<float>> inputs,
                    const MfOptions& options, std::span<MfOutput<float>> outputs) noexcept;

/// The number of lanes evaluate_batch uses: 16 on x86-64 with AVX-512, 8 on other x86-64 (GCC
/// builds), 4 elsewhere.
int batch_lanes() noexcept;

/// Whether evaluate_batch_on(16, …) runs 16 lanes (the CPU is x86-64-v4: AVX-512 and the rest).
bool sixteen_lanes_available() noexcept;

/// evaluate_batch on `lanes` lanes (x86-64, GCC): 16 where sixteen_lanes_available(), else 8. Elsewhere
/// batch_lanes(), whatever `lanes` is.
void evaluate_batch_on(int lanes, const MfParameters<float>& params,
                       std::span<const MfInput<float>> inputs, const MfOptions& options,
                       std::span<MfOutput<float>> outputs) noexcept;

}  // namespace tread::mf
