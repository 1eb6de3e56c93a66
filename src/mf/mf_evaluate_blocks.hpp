#pragma once
// The blocks of an evaluate_batch (mf_evaluate_batch.hpp): N wheels packed into
// MfInput<Lanes<N>>, evaluated once, unpacked; the last, partial block padded with copies of its
// first wheel. Everything here is always inlined into the function of one width and one
// instruction set that runs the blocks: the baseline evaluate_eight in mf_evaluate_batch.cpp, the
// AVX2 one (evaluate_eight_v3) in mf_evaluate_batch_v3.cpp and the AVX-512 one
// (evaluate_sixteen_v4) in mf_evaluate_batch_v4.cpp, each compiled for its level as a whole (see
// there and src/mf/CMakeLists.txt why). Internal linkage (static) throughout: a copy left out of
// line stays in its file, compiled for that file's target, and is never shared between the
// baseline, the x86-64-v3 and the x86-64-v4 code.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <span>
#include <type_traits>

#include "mf/mf_evaluate_batch.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_lane_transpose.hpp"
#include "mf/mf_lanes.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace tread::mf::batch {

constexpr std::size_t kInputFields = sizeof(MfInput<float>) / sizeof(float);
constexpr std::size_t kOutputFields = offsetof(MfOutput<float>, status) / sizeof(float);
static_assert(std::is_standard_layout_v<MfInput<float>> && kInputFields == 7);
static_assert(offsetof(MfOutput<float>, kxk_n) == (kOutputFields - 1) * sizeof(float));

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// The 16-lane outputs into 16 wheels' rows, 16 fields at a time: a 16 × 16 transpose in AVX-512
/// registers (unpack, in-lane shuffle, two 128-bit-lane shuffles: 64 instructions) and one
/// (masked for the last 13 fields) store per wheel and group, instead of 29 × 16 scalar moves.
/// Inlined into evaluate_sixteen_v4 only (mf_evaluate_batch_v4.cpp, the same target). GCC 12 warns
/// that the _mm512_undefined_ps() inside its own shuffle intrinsics may be used uninitialized (a
/// known false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
__attribute__((target("arch=x86-64-v4"))) static inline void store_rows16(
    const char* lanes, MfOutput<float>* outputs) {
  for (std::size_t first = 0; first < kOutputFields; first += 16) {
    const std::size_t fields = std::min<std::size_t>(16, kOutputFields - first);
    __m512 r[16];
    for (std::size_t f = 0; f < 16; ++f) {
      r[f] =
          f < fields ? _mm512_loadu_ps(lanes + (first + f) * sizeof(__m512)) : _mm512_setzero_ps();
    }
    __m512 t[16];
    for (std::size_t k = 0; k < 16; k += 2) {
      t[k] = _mm512_unpacklo_ps(r[k], r[k + 1]);
      t[k + 1] = _mm512_unpackhi_ps(r[k], r[k + 1]);
    }
    __m512 u[16];
    for (std::size_t k = 0; k < 16; k += 4) {
      u[k] = _mm512_shuffle_ps(t[k], t[k + 2], _MM_SHUFFLE(1, 0, 1, 0));
      u[k + 1] = _mm512_shuffle_ps(t[k], t[k + 2], _MM_SHUFFLE(3, 2, 3, 2));
      u[k + 2] = _mm512_shuffle_ps(t[k + 1], t[k + 3], _MM_SHUFFLE(1, 0, 1, 0));
      u[k + 3] = _mm512_shuffle_ps(t[k + 1], t[k + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    __m512 v[16];
    for (std::size_t k = 0; k < 16; k += 8) {
      for (std::size_t j = 0; j < 4; ++j) {
        v[k + j] = _mm512_shuffle_f32x4(u[k + j], u[k + j + 4], 0x88);
        v[k + j + 4] = _mm512_shuffle_f32x4(u[k + j], u[k + j + 4], 0xdd);
      }
    }
    const auto mask = static_cast<__mmask16>((1U << fields) - 1U);
    for (std::size_t j = 0; j < 8; ++j) {
      const __m512 lo = _mm512_shuffle_f32x4(v[j], v[j + 8], 0x88);
      const __m512 hi = _mm512_shuffle_f32x4(v[j], v[j + 8], 0xdd);
      _mm512_mask_storeu_ps(reinterpret_cast<char*>(&outputs[j]) + first * sizeof(float), mask, lo);
      _mm512_mask_storeu_ps(reinterpret_cast<char*>(&outputs[j + 8]) + first * sizeof(float), mask,
                            hi);
    }
  }
}
#pragma GCC diagnostic pop
#endif

static_assert(kOutputFields > 24 && kOutputFields <= 32);

/// Fields kFirst … kFirst + kCount − 1 of eight wheels, from their lanes (8 floats a field) into
/// the wheels' rows: one 8 × 8 transpose and one store per wheel. Sizes known at compile time and
/// loops unrolled: with the group's size a variable, GCC -O2 compiled this as loops of 8-byte
/// moves through memory, 17 % of the 8-lane batch's time.
template <std::size_t kFirst, std::size_t kCount>
[[gnu::always_inline]] static inline void store_rows8(const char* lanes_bytes,
                                                      MfOutput<float>* outputs) {
  static_assert(kCount >= 1 && kCount <= 8 && kFirst + kCount <= kOutputFields);
  using W = lanes::FloatVec<8>;
  W group[8];
#pragma GCC unroll 8
  for (std::size_t f = 0; f < 8; ++f) {
    std::memcpy(&group[f], lanes_bytes + (kFirst + (f < kCount ? f : 0)) * sizeof(W), sizeof(W));
  }
  W rows[8];
  lanes::transpose<8>(group, rows);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < 8; ++i) {
    std::memcpy(reinterpret_cast<char*>(&outputs[i]) + kFirst * sizeof(float), &rows[i],
                kCount * sizeof(float));
  }
}

/// N wheels: inputs packed field by field into lanes, evaluated, outputs unpacked.
template <int N>
[[gnu::always_inline]] static inline void evaluate_block(const MfParameters<float>& params,
                                                         const MfInput<float>* inputs,
                                                         const MfOptions& options, bool mirror,
                                                         MfOutput<float>* outputs) {
  using L = lanes::Lanes<N>;
  static_assert(std::is_standard_layout_v<MfOutput<L>> &&
                offsetof(MfOutput<L>, status) == kOutputFields * sizeof(L));
  constexpr auto kWheels = static_cast<std::size_t>(N);
  if constexpr (N == 4) {
    // Four lanes (where the CPU has no wider vectors) are evaluate_four's, packing and unpacking
    // included: each wheel on the batch's mounted side.
    std::array<MfInput<float>, 4> four;
    std::copy_n(inputs, 4, four.begin());
    const std::array<MountedSide, 4> sides = {options.side, options.side, options.side,
                                              options.side};
    std::array<MfOutput<float>, 4> result;
    evaluate_four(params, four, options, sides, result);
    std::copy_n(result.begin(), 4, outputs);
    static_cast<void>(mirror);  // evaluate_four mirrors by `sides`
  } else {
    // In and out of lanes by transposes in registers at 8 lanes and (out) at 16; else (the 16
    // lanes' inputs) through plain float arrays in memory: element access of a vector held in
    // registers would be one insert or extract per float.
    std::array<lanes::FloatVec<N>, kInputFields> packed;
    if constexpr (N == 8) {
      // Each wheel's 7 fields and the next wheel's first (the last wheel's 8th float is 0), as a
      // row of eight; the transpose's first 7 columns are the fields.
      lanes::FloatVec<8> rows[8];
      lanes::FloatVec<8> columns[8];
#pragma GCC unroll 8
      for (std::size_t i = 0; i < kWheels; ++i) {
        rows[i] = lanes::FloatVec<8>{};
        std::memcpy(&rows[i], reinterpret_cast<const char*>(&inputs[i]),
                    i + 1 < kWheels ? sizeof(rows[i]) : sizeof(MfInput<float>));
      }
      lanes::transpose<8>(rows, columns);
      std::memcpy(packed.data(), columns, sizeof(packed));
    } else {
      float rows_in[kWheels][kInputFields];
      std::memcpy(rows_in, reinterpret_cast<const char*>(inputs), sizeof(rows_in));
      float columns_in[kInputFields][kWheels];
      for (std::size_t i = 0; i < kWheels; ++i) {
        for (std::size_t f = 0; f < kInputFields; ++f) columns_in[f][i] = rows_in[i][f];
      }
      std::memcpy(packed.data(), columns_in, sizeof(packed));
    }
    MfInput<L> in;
    in.fz_n = L(packed[0]);
    in.kappa = L(packed[1]);
    in.alpha_rad = L(packed[2]);
    in.gamma_rad = L(packed[3]);
    in.vx_mps = L(packed[4]);
    in.phit_1pm = L(packed[5]);
    in.p_pa = L(packed[6]);
    lanes::Mask<N> flip;
    if (mirror) flip = !flip;
    MfOptions lane_options = options;
    lane_options.side = MountedSide::as_measured;
    MfOutput<L> out = evaluate(params, detail::mirror_input(in, flip), lane_options);
    detail::mirror_output(out, flip);
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
    constexpr bool kRows16 = N == 16;
#else
    constexpr bool kRows16 = false;
#endif
    if constexpr (N == 8) {
      // Eight fields at a time transposed into the eight wheels' rows (the last group's 5 fields
      // stored alone: the status follows them).
      const char* lanes_bytes = reinterpret_cast<const char*>(&out);
      store_rows8<0, 8>(lanes_bytes, outputs);
      store_rows8<8, 8>(lanes_bytes, outputs);
      store_rows8<16, 8>(lanes_bytes, outputs);
      store_rows8<24, kOutputFields - 24>(lanes_bytes, outputs);
    } else if constexpr (kRows16) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
      // _mm512_loadu_ps reads through a may_alias type: straight from the lanes.
      store_rows16(reinterpret_cast<const char*>(&out), outputs);
#endif
    } else {
      float columns_out[kOutputFields][kWheels];
      std::memcpy(columns_out, reinterpret_cast<const char*>(&out), sizeof(columns_out));
      for (std::size_t i = 0; i < kWheels; ++i) {
        float row[kOutputFields];
        for (std::size_t f = 0; f < kOutputFields; ++f) row[f] = columns_out[f][i];
        std::memcpy(reinterpret_cast<char*>(&outputs[i]), row, sizeof(row));
      }
    }
    const auto status = out.status.each();
    for (std::size_t i = 0; i < kWheels; ++i) outputs[i].status = status[i];
  }
}

/// The blocks of a batch, one after the other. The parameters and options are copied first: GCC
/// cannot tell that the outputs' stores leave the caller's MfParameters alone (both hold floats),
/// so it loaded the parameters again in each block and recomputed what depends on them only; of a
/// local copy whose address does not escape, it keeps such values across blocks (callgrind, per
/// 8-lane block: MF 6.1 4 407 → 4 300 instructions, MF 6.2 5 700 → 5 585).
template <int N>
[[gnu::always_inline]] static inline void evaluate_blocks(const MfParameters<float>& caller_params,
                                                          std::span<const MfInput<float>> inputs,
                                                          const MfOptions& caller_options,
                                                          std::span<MfOutput<float>> outputs) {
  const MfParameters<float> params = caller_params;
  const MfOptions options = caller_options;
  const bool mirror = mirrored(options.side, params.tyre_side);
  const std::size_t n = std::min(inputs.size(), outputs.size());
  std::size_t i = 0;
  for (; i + N <= n; i += N) evaluate_block<N>(params, &inputs[i], options, mirror, &outputs[i]);
  if (i < n) {
    std::array<MfInput<float>, static_cast<std::size_t>(N)> tail_in;
    std::array<MfOutput<float>, static_cast<std::size_t>(N)> tail_out;
    tail_in.fill(inputs[i]);
    std::copy(inputs.begin() + static_cast<std::ptrdiff_t>(i),
              inputs.begin() + static_cast<std::ptrdiff_t>(n), tail_in.begin());
    evaluate_block<N>(params, tail_in.data(), options, mirror, tail_out.data());
    std::copy(tail_out.begin(), tail_out.begin() + static_cast<std::ptrdiff_t>(n - i),
              outputs.begin() + static_cast<std::ptrdiff_t>(i));
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// The 8-lane batch compiled for x86-64-v3 (AVX2, FMA): mf_evaluate_batch_v3.cpp. Call only where
/// the CPU is x86-64-v3.
void evaluate_eight_v3(const MfParameters<float>& params, std::span<const MfInput<float>> inputs,
                       const MfOptions& options, std::span<MfOutput<float>> outputs) noexcept;
/// The 16-lane batch compiled for x86-64-v4 (AVX-512): mf_evaluate_batch_v4.cpp. Call only where
/// the CPU is x86-64-v4.
void evaluate_sixteen_v4(const MfParameters<float>& params, std::span<const MfInput<float>> inputs,
                         const MfOptions& options, std::span<MfOutput<float>> outputs) noexcept;
#endif

}  // namespace tread::mf::batch
