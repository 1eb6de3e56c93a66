#pragma once
// The Magic Formula in fixed point: mf::evaluate on fixed::Fixed64 (Q31.32, integer arithmetic
// only) — the same templated source as the double and float paths (mf_evaluate.hpp), instantiated
// once in the core (mf_evaluate_fixed.cpp). For cores without an FPU; on the host it evaluates the
// exact target arithmetic (`tread mf eval --fixed`).
//
// Parameters: on a target they come pre-scaled from the .tir → header generator (every literal a
// consteval Fixed64 constant); on the host, to_fixed_parameters converts a loaded file's.
// An intermediate that overflows Q31.32 makes the outputs it reaches invalid; they are returned as
// 0 with Status::non_finite, as a NaN is in floating point.

#include "fixed/fixed64.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_types.hpp"

namespace tread::mf {

using fixed::Fixed64;

/// Host only (run-time double → Q31.32, rounded to nearest): the parameters in fixed point. A
/// coefficient outside ±2^31 becomes invalid (and every output that uses it non_finite).
MfParameters<Fixed64> to_fixed_parameters(const MfParameters<double>& p);

template <typename T, typename P>
MfOutput<T> evaluate(const MfParameters<P>& params, const MfInput<T>& input,
                     const MfOptions& options);

extern template MfOutput<Fixed64> evaluate<Fixed64, Fixed64>(const MfParameters<Fixed64>&,
                                                             const MfInput<Fixed64>&,
                                                             const MfOptions&);

}  // namespace tread::mf
