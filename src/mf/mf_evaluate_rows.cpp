// evaluate_rows: evaluate<double> on two double lanes (mf_double_lanes.hpp) where that gives
// evaluate<double>'s bits, else one point at a time. This file is compiled -ffp-contract=off (and,
// like the other lane files, without sanitizer instrumentation; -O3: src/mf/CMakeLists.txt).
//
// Two lanes, not four: on the AVX2 VM (`tread mf eval --columns Fx_N,Fy_N,Mz_Nm`, 1 M rows, seven
// alternating runs) two lanes took 6–11 % less CPU than evaluate<double> row by row, four lanes
// 14 % more (the values of four lanes in two SSE registers each, spilled around every libm call).
#include "mf/mf_evaluate_rows.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>

// Where evaluate<double> (mf_evaluate.cpp, built for the same CPU as this file) cannot contract
// a·b + c into an FMA either, so that the lanes give its bits: x86-64 built for a CPU without FMA
// (the baseline the presets build for). The optimisation and the sanitizers may differ between
// the two files (the asan preset builds mf_evaluate.cpp -O1 and instrumented): IEEE double
// arithmetic on SSE2 gives the same bits either way. Elsewhere the lanes are not compiled.
#if defined(__x86_64__) && !defined(__FMA__)
#define TREAD_ROWS_IN_PAIRS 1
#include "mf/mf_double_lanes.hpp"
#endif

namespace tread::mf {

namespace {

#if defined(TREAD_ROWS_IN_PAIRS)
constexpr int kLanes = 2;

// The block with everything inlined, and (GCC) a clone for x86-64-v3 that the loader picks where
// the CPU has it: VEX encodings, no FMA here (-ffp-contract=off), the same bits; 5 % less CPU than
// the baseline code in the measurement above.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TREAD_ROWS_FUNCTION __attribute__((flatten, target_clones("arch=x86-64-v3", "default")))
#else
#define TREAD_ROWS_FUNCTION __attribute__((flatten))
#endif

template <int N>
using DL = dlanes::DLanes<N>;

constexpr std::size_t kInputFields = sizeof(MfInput<double>) / sizeof(double);
constexpr std::size_t kOutputFields = offsetof(MfOutput<double>, status) / sizeof(double);
static_assert(std::is_standard_layout_v<MfInput<double>> && kInputFields == 7);
static_assert(std::is_trivially_copyable_v<MfInput<DL<2>>> &&
              std::is_trivially_copyable_v<MfOutput<DL<2>>>);
static_assert(offsetof(MfOutput<double>, kxk_n) == (kOutputFields - 1) * sizeof(double));
static_assert(sizeof(MfInput<DL<2>>) == kInputFields * sizeof(DL<2>));
static_assert(offsetof(MfOutput<DL<2>>, status) == kOutputFields * sizeof(DL<2>));
// A DL<2> is its two doubles, lane 0 first (evaluate_two copies lane i from byte 8·i).
static_assert(std::is_standard_layout_v<DL<2>> && sizeof(DL<2>) == 2 * sizeof(double) &&
              offsetof(DL<2>, v) == 0);

// n (1 or 2) points: lane i takes point i, a lone point is evaluated in both lanes.
TREAD_ROWS_FUNCTION void evaluate_two(const MfParameters<double>& params, const MfInput<double>* in,
                                      std::size_t n, const MfOptions& options,
                                      MfOutput<double>* out) noexcept {
  // MfInput and MfOutput are runs of their scalar (MfOutput: then its status), copied as such.
  double first[kInputFields];
  double second[kInputFields];
  std::memcpy(first, &in[0], sizeof first);
  std::memcpy(second, &in[n > 1 ? 1 : 0], sizeof second);
  DL<2> in_fields[kInputFields];
  for (std::size_t f = 0; f < kInputFields; ++f) in_fields[f].v = DL<2>::D{first[f], second[f]};
  MfInput<DL<2>> lanes_in;
  std::memcpy(static_cast<void*>(&lanes_in), in_fields, sizeof in_fields);
  const MfOutput<DL<2>> r = evaluate(params, lanes_in, options);
  // Field f of lane i is the double at byte 16·f + 8·i of r, and goes to byte 8·f of out[i]:
  // copied straight there, a double at a time (no copy of r as a whole, no loop per lane).
  const auto* from = reinterpret_cast<const unsigned char*>(&r);
  for (std::size_t i = 0; i < n; ++i) {
    auto* to = reinterpret_cast<unsigned char*>(&out[i]);
    for (std::size_t f = 0; f < kOutputFields; ++f) {
      std::memcpy(to + f * sizeof(double), from + f * sizeof(DL<2>) + i * sizeof(double),
                  sizeof(double));
    }
    out[i].status = r.status[static_cast<int>(i)];
  }
}
#else
constexpr int kLanes = 1;
#endif

}  // namespace

void evaluate_rows(const MfParameters<double>& params, std::span<const MfInput<double>> inputs,
                   const MfOptions& options, std::span<MfOutput<double>> outputs) noexcept {
  const std::size_t n = std::min(inputs.size(), outputs.size());
#if defined(TREAD_ROWS_IN_PAIRS)
  for (std::size_t i = 0; i < n; i += 2) {
    evaluate_two(params, inputs.data() + i, std::min<std::size_t>(2, n - i), options,
                 outputs.data() + i);
  }
#else
  for (std::size_t i = 0; i < n; ++i) outputs[i] = evaluate(params, inputs[i], options);
#endif
}

int rows_lanes() noexcept {
  return kLanes;
}

}  // namespace tread::mf
