// Rows of floats ↔ lanes: an N × N transpose of generic float vectors in registers, for packing
// wheels' structs into lanes and unpacking them (mf_evaluate_four.cpp, mf_evaluate_batch.cpp).
#pragma once

#include <cstddef>

#include "mf/mf_lanes.hpp"

namespace tread::mf::lanes {

/// N rows of N floats → their columns: out[j] = {in[0][j], …, in[N − 1][j]}, in registers, as
/// generic-vector shuffles (4: unpack pairs, then pairs of pairs; 8: the same within each 128-bit
/// half, then the halves: 24 shuffles, which the AVX2 clone compiles to unpcklps/shufps/vperm2f128
/// and the SSE2 one to pairs of 4-lane shuffles) instead of N² scalar moves through memory.
template <int N>
[[gnu::always_inline]] inline void transpose(const FloatVec<N> (&in)[static_cast<std::size_t>(N)],
                                             FloatVec<N> (&out)[static_cast<std::size_t>(N)]) {
  using W = FloatVec<N>;
  if constexpr (N == 4) {
    const W t0 = __builtin_shufflevector(in[0], in[1], 0, 4, 1, 5);
    const W t1 = __builtin_shufflevector(in[0], in[1], 2, 6, 3, 7);
    const W t2 = __builtin_shufflevector(in[2], in[3], 0, 4, 1, 5);
    const W t3 = __builtin_shufflevector(in[2], in[3], 2, 6, 3, 7);
    out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    out[2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
  } else {
    static_assert(N == 8);
    // Unrolled: as loops (GCC -O2 keeps them), every step went through memory.
    W t[8];
#pragma GCC unroll 8
    for (std::size_t k = 0; k < 8; k += 2) {
      t[k] = __builtin_shufflevector(in[k], in[k + 1], 0, 8, 1, 9, 4, 12, 5, 13);
      t[k + 1] = __builtin_shufflevector(in[k], in[k + 1], 2, 10, 3, 11, 6, 14, 7, 15);
    }
    W u[8];
#pragma GCC unroll 8
    for (std::size_t k = 0; k < 8; k += 4) {
      u[k] = __builtin_shufflevector(t[k], t[k + 2], 0, 1, 8, 9, 4, 5, 12, 13);
      u[k + 1] = __builtin_shufflevector(t[k], t[k + 2], 2, 3, 10, 11, 6, 7, 14, 15);
      u[k + 2] = __builtin_shufflevector(t[k + 1], t[k + 3], 0, 1, 8, 9, 4, 5, 12, 13);
      u[k + 3] = __builtin_shufflevector(t[k + 1], t[k + 3], 2, 3, 10, 11, 6, 7, 14, 15);
    }
#pragma GCC unroll 8
    for (std::size_t j = 0; j < 4; ++j) {
      out[j] = __builtin_shufflevector(u[j], u[j + 4], 0, 1, 2, 3, 8, 9, 10, 11);
      out[j + 4] = __builtin_shufflevector(u[j], u[j + 4], 4, 5, 6, 7, 12, 13, 14, 15);
    }
  }
}

}  // namespace tread::mf::lanes
