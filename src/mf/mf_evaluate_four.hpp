#pragma once
// Four wheels in one evaluation: the Magic Formula (mf_evaluate.hpp) instantiated on four float
// lanes (mf_lanes.hpp). For a node with four road wheels on the same tyre: the cost of about one
// and a half scalar evaluations for four wheels on x86-64 (SSE) and aarch64 (NEON).
// The results equal evaluate<float>'s within float rounding (the lanes' exp/log/sin/cos differ from
// libm's in the last bits), not bit for bit; tests/mf/mf_evaluate_four_test.cpp checks them against
// MFeval at the float tolerance and against the scalar path.

#include <array>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_lanes.hpp"

namespace tread::mf {

/// Whether the target has a vector unit for the lanes (x86-64 SSE2, aarch64 NEON). Without one
/// evaluate_four is correct but no faster than four scalar evaluations, and callers such as the
/// node evaluate wheel by wheel instead.
#if defined(__SSE2__) || (defined(__ARM_NEON) && defined(__aarch64__))
inline constexpr bool kVectorLanes = true;
#else
inline constexpr bool kVectorLanes = false;
#endif

/// Evaluates four wheels with the same parameters and options; wheel i is mounted on `sides[i]`
/// (options.side is not used). Never allocates, never throws; never returns NaN or inf (a
/// non-finite output is 0 and its wheel's status Status::non_finite, as evaluate).
void evaluate_four(const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
                   const MfOptions& options, const std::array<MountedSide, 4>& sides,
                   std::array<MfOutput<float>, 4>& outputs) noexcept;

/// The same, leaving the results in lanes (wheel i in lane i of every member, status per-lane
/// masks, out.status[i] wheel i's Status): for a caller that needs a few outputs, e.g.
/// `out.fx_n[i]`.
void evaluate_four(const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
                   const MfOptions& options, const std::array<MountedSide, 4>& sides,
                   MfOutput<lanes::F4>& outputs) noexcept;

namespace detail {
/// evaluate_four without its x86-64-v4 code: on x86-64 with GCC the x86-64-v3 clone (the baseline
/// clone on a CPU without AVX2 and FMA), elsewhere evaluate_four itself. For the test that the v4
/// code's bits are the v3 clone's (MfEvaluateFour.X8664V4EqualsV3BitForBit).
void evaluate_four_without_v4(const MfParameters<float>& params,
                              const std::array<MfInput<float>, 4>& inputs, const MfOptions& options,
                              const std::array<MountedSide, 4>& sides,
                              MfOutput<lanes::F4>& outputs) noexcept;
}  // namespace detail

}  // namespace tread::mf
