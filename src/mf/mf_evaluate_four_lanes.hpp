#pragma once
// The four-lane evaluation's body (evaluate_four, mf_evaluate_four.hpp): packs four wheels'
// inputs, evaluates once on Lanes<4>, mirrors per wheel. Inlined into the function of one
// instruction set that runs it: evaluate_four's clones for x86-64-v3 and the SSE2 baseline in
// mf_evaluate_four.cpp (GCC target_clones), and evaluate_four_v4 in mf_evaluate_four_v4.cpp,
// compiled for x86-64-v4 as a whole so that AVX-512VL's selects are used (lanes::if_else).
// Internal linkage (static) throughout: a copy left out of line stays in its file, compiled for
// that file's target, and is never shared between the levels.
#include <array>
#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_lane_transpose.hpp"
#include "mf/mf_lanes.hpp"

namespace tread::mf::four {

// MfInput is a run of floats: packing transposes four of them at a time.
constexpr std::size_t kInputFields = sizeof(MfInput<float>) / sizeof(float);
static_assert(std::is_standard_layout_v<MfInput<float>> && kInputFields == 7);
static_assert(offsetof(MfInput<float>, fz_n) == 0 * sizeof(float) &&
              offsetof(MfInput<float>, kappa) == 1 * sizeof(float) &&
              offsetof(MfInput<float>, alpha_rad) == 2 * sizeof(float) &&
              offsetof(MfInput<float>, gamma_rad) == 3 * sizeof(float) &&
              offsetof(MfInput<float>, vx_mps) == 4 * sizeof(float) &&
              offsetof(MfInput<float>, phit_1pm) == 5 * sizeof(float) &&
              offsetof(MfInput<float>, p_pa) == 6 * sizeof(float));

/// Four consecutive floats of each wheel's input, from float `field` on.
[[gnu::always_inline]] static inline void load_rows(const std::array<MfInput<float>, 4>& wheels,
                                                    std::size_t field, lanes::V (&rows)[4]) {
  for (std::size_t i = 0; i < 4; ++i) {
    std::memcpy(&rows[i], reinterpret_cast<const char*>(&wheels[i]) + field * sizeof(float),
                sizeof(lanes::V));
  }
}

/// Four wheels' inputs in lanes, and which of them are mirrored (y → −y on the way in and out of
/// its lane). The entry points call evaluate themselves: GCC's flatten left a dozen of the
/// evaluation's functions out of line where the call was one level down, in a function of this
/// header.
[[gnu::always_inline]] static inline MfInput<lanes::F4> pack_inputs(
    const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
    const std::array<MountedSide, 4>& sides, lanes::Mask4& mirror) noexcept {
  using lanes::F4;
  using lanes::V;
  for (std::size_t i = 0; i < 4; ++i) {
    mirror.m[i] = mirrored(sides[i], params.tyre_side) ? -1 : 0;
  }
  // Floats 0–3 and 3–6 of each wheel, transposed.
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
  return detail::mirror_input(in, mirror);
}

/// The options the lanes are evaluated with: each wheel's side is its lane's mirroring.
[[gnu::always_inline]] static inline MfOptions lane_options(const MfOptions& options) noexcept {
  MfOptions o = options;
  o.side = MountedSide::as_measured;
  return o;
}

// An entry point's body, the same in each (a macro so that evaluate is called in the flattened
// function itself): the result built in place (a prvalue initializing `out` directly), not
// assigned: assignment copied the 480-byte result from evaluate's return slot, about 2 % of an
// evaluation. MfOutput<F4> is trivially destructible, so ending the old object's lifetime this way
// needs no destructor call.
static_assert(std::is_trivially_destructible_v<MfOutput<lanes::F4>>);
#define TREAD_EVALUATE_FOUR_BODY(params, inputs, options, sides, out)                      \
  do {                                                                                     \
    ::tread::mf::lanes::Mask4 four_mirror;                                                 \
    const ::tread::mf::MfInput<::tread::mf::lanes::F4> four_in =                           \
        ::tread::mf::four::pack_inputs(params, inputs, sides, four_mirror);                \
    ::new (static_cast<void*>(&(out)))::tread::mf::MfOutput<::tread::mf::lanes::F4>(       \
        ::tread::mf::evaluate(params, four_in, ::tread::mf::four::lane_options(options))); \
    ::tread::mf::detail::mirror_output(out, four_mirror);                                  \
  } while (false)

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// evaluate_four for x86-64-v4 CPUs (mf_evaluate_four_v4.cpp); mf_evaluate_four.cpp calls it only
/// where the CPU is one.
void evaluate_four_v4(const MfParameters<float>& params,
                      const std::array<MfInput<float>, 4>& inputs, const MfOptions& options,
                      const std::array<MountedSide, 4>& sides, MfOutput<lanes::F4>& out) noexcept;
#endif

}  // namespace tread::mf::four
