#pragma once
// Many operating points of one tyre in double, each exactly as evaluate<double> gives it (bit for
// bit, the same status): for offline work where the output must not change with how it was
// computed (`tread mf eval` in double). On x86-64 (without FMA in the core's build) the points go
// through evaluate on double lanes (mf_double_lanes.hpp), two at a time; elsewhere one by
// one through evaluate<double>.

#include <span>

#include "mf/mf_evaluate.hpp"

namespace tread::mf {

/// Evaluates inputs[i] into outputs[i] for every i (the spans have the same length): outputs[i] is
/// evaluate(params, inputs[i], options), bit for bit. Never allocates, never throws.
void evaluate_rows(const MfParameters<double>& params, std::span<const MfInput<double>> inputs,
                   const MfOptions& options, std::span<MfOutput<double>> outputs) noexcept;

/// Points evaluate_rows computes in one pass: 1 where it evaluates them one by one.
int rows_lanes() noexcept;

}  // namespace tread::mf
