#pragma once
// A road-wheel channel on the Magic Formula core (float): clamps the inputs to the property file's
// limits (FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX) and flags it, then evaluates.
// Fz < 0 is taken as 0 (lifted wheel: zero forces) and flagged. A non-finite model output
// (defective parameters, a NaN input) is reported as TyreResult::non_finite; the node then sends
// zeros, flagged.
// Optional relaxation (mf_transient.hpp): the Magic Formula sees the slips lagging the received
// (kinematic) ones with the tyre's relaxation lengths; reset() (the node calls it while a wheel is
// stale) restarts the lag from the next received slips.
// The node's due wheels go through evaluate_wheels: on targets with vector lanes, when all due
// wheels share one tyre and its options (the mounted side may differ), they are evaluated in one
// pass of four lanes (mf::evaluate_four); otherwise (e.g. other tyres on the rear axle), a single
// due wheel, and on the ECU's scalar build, one by one.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_transient.hpp"
#include "node/channels.hpp"

namespace tread::node {

class MfTyreChannel {
 public:
  MfTyreChannel() = default;
  /// `params` must outlive the channel. `relaxation`: first-order transient slips.
  /// The node sends Rl alone of the extras: without relaxation the contact patch and relaxation
  /// lengths are skipped.
  MfTyreChannel(const mf::MfParameters<float>& params, const mf::MfOptions& options,
                bool relaxation = false) noexcept
      : params_(&params), options_(options), relaxation_(relaxation) {
    options_.extras = true;
    options_.extras_loaded_radius_only = !relaxation;
  }

  TyreResult evaluate(const proto::WheelInput& in, float dt_s) noexcept {
    TyreResult result;
    if (params_ == nullptr) {
      return result;
    }
    const mf::MfInput<float> input = limited(in, result.clamped);
    mf::MfOutput<float> out;
    if (relaxation_) {
      restart_if_due(input);
      out = transient_.step(*params_, input, options_, dt_s);
    } else {
      out = mf::evaluate(*params_, input, options_);
    }
    result.fx_n = out.fx_n;
    result.fy_n = out.fy_n;
    result.mz_nm = out.mz_nm;
    result.mx_nm = out.mx_nm;
    result.my_nm = out.my_nm;
    result.rl_m = out.rl_m;
    result.clamped = result.clamped || out.status == Status::out_of_range;
    result.non_finite = out.status == Status::non_finite;
    return result;
  }

  /// The node's due wheels (bit i of `due`: tyres[i] with inputs[i] → results[i]).
  static void evaluate_wheels(std::span<MfTyreChannel> tyres,
                              std::span<const proto::WheelInput> inputs, std::uint8_t due,
                              float dt_s, std::span<TyreResult> results) noexcept {
    const std::size_t n = std::min({tyres.size(), inputs.size(), results.size()});
    if constexpr (mf::kVectorLanes) {
      const auto in_range = static_cast<unsigned>(due) & ((1U << std::min<std::size_t>(n, 8)) - 1U);
      if (n <= 4 && std::popcount(in_range) > 1 && same_tyre(tyres.first(n), due)) {
        evaluate_lanes(tyres.first(n), inputs, due, dt_s, results);
        return;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (is_due(due, i)) results[i] = tyres[i].evaluate(inputs[i], dt_s);
    }
  }

  /// Restarts the relaxation from the next received slips.
  void reset() noexcept { restart_ = true; }

  /// The transient slips (the received ones without relaxation).
  [[nodiscard]] const mf::MfTransient<float>& transient() const noexcept { return transient_; }

 private:
  void restart_if_due(const mf::MfInput<float>& input) noexcept {
    if (restart_) {
      transient_.reset(input.kappa, input.alpha_rad);
      restart_ = false;
    }
  }

  /// The input clamped to the file's limits; `clamped` set when a limit applied.
  mf::MfInput<float> limited(const proto::WheelInput& in, bool& clamped) const noexcept {
    const mf::MfParameters<float>& p = *params_;
    const auto clamp = [&clamped](float v, float lo, float hi) {
      if (v < lo) {
        clamped = true;
        return lo;
      }
      if (v > hi) {
        clamped = true;
        return hi;
      }
      return v;
    };
    mf::MfInput<float> input;
    input.fz_n = clamp(in.fz_n, 0.0F, p.fzmax_n);
    input.kappa = clamp(in.kappa, p.kpumin, p.kpumax);
    input.alpha_rad = clamp(in.alpha_rad, p.alpmin_rad, p.alpmax_rad);
    input.gamma_rad = clamp(in.gamma_rad, p.cammin_rad, p.cammax_rad);
    input.vx_mps = in.vx_mps;
    return input;
  }

  /// Whether the due wheels share parameters and options (all but the mounted side).
  static bool same_tyre(std::span<const MfTyreChannel> tyres, std::uint8_t due) noexcept {
    const MfTyreChannel* first = nullptr;
    for (std::size_t i = 0; i < tyres.size(); ++i) {
      if (!is_due(due, i)) continue;
      const MfTyreChannel& t = tyres[i];
      if (t.params_ == nullptr) return false;
      if (first == nullptr) {
        first = &t;
        continue;
      }
      const mf::MfOptions& a = first->options_;
      const mf::MfOptions& b = t.options_;
      if (t.params_ != first->params_ || t.relaxation_ != first->relaxation_ ||
          a.use_limits != b.use_limits || a.use_alpha_star != b.use_alpha_star ||
          a.use_turn_slip != b.use_turn_slip || a.combined != b.combined || a.extras != b.extras ||
          a.extras_loaded_radius_only != b.extras_loaded_radius_only) {
        return false;
      }
    }
    return first != nullptr;
  }

  /// Up to four due wheels of one tyre in one pass of four lanes (wheels not due: Fz = 0). With
  /// relaxation: the transient slips advanced per wheel, then one pass; a wheel whose relaxation
  /// restarted takes its relaxation lengths from one more pass first (as MfTransient::step).
  static void evaluate_lanes(std::span<MfTyreChannel> tyres,
                             std::span<const proto::WheelInput> inputs, std::uint8_t due,
                             float dt_s, std::span<TyreResult> results) noexcept {
    const MfTyreChannel* first = nullptr;
    std::array<mf::MfInput<float>, 4> in{};
    std::array<mf::MountedSide, 4> sides{};
    std::array<bool, 4> clamped{};
    bool need_lengths = false;
    for (std::size_t i = 0; i < tyres.size(); ++i) {
      if (!is_due(due, i)) continue;
      MfTyreChannel& t = tyres[i];
      if (first == nullptr) first = &t;
      in[i] = t.limited(inputs[i], clamped[i]);
      sides[i] = t.options_.side;
      if (t.relaxation_) {
        t.restart_if_due(in[i]);
        need_lengths = need_lengths || !t.transient_.has_relaxation_lengths();
      }
    }
    mf::MfOutput<mf::lanes::F4> out;
    if (first->relaxation_) {
      if (need_lengths) {
        std::array<mf::MfInput<float>, 4> probe = in;
        for (std::size_t i = 0; i < tyres.size(); ++i) {
          if (is_due(due, i)) probe[i] = tyres[i].transient_.probe(in[i]);
        }
        mf::evaluate_four(*first->params_, probe, first->options_, sides, out);
        for (std::size_t i = 0; i < tyres.size(); ++i) {
          mf::MfTransient<float>& tr = tyres[i].transient_;
          if (is_due(due, i) && !tr.has_relaxation_lengths()) {
            const int lane = static_cast<int>(i);
            tr.set_relaxation_lengths(out.sigmax_m[lane], out.sigmay_m[lane]);
          }
        }
      }
      for (std::size_t i = 0; i < tyres.size(); ++i) {
        if (is_due(due, i)) in[i] = tyres[i].transient_.advance(in[i], dt_s);
      }
    }
    mf::evaluate_four(*first->params_, in, first->options_, sides, out);
    for (std::size_t i = 0; i < tyres.size(); ++i) {
      if (!is_due(due, i)) continue;
      const int lane = static_cast<int>(i);
      TyreResult& r = results[i];
      r.fx_n = out.fx_n[lane];
      r.fy_n = out.fy_n[lane];
      r.mz_nm = out.mz_nm[lane];
      r.mx_nm = out.mx_nm[lane];
      r.my_nm = out.my_nm[lane];
      r.rl_m = out.rl_m[lane];
      r.clamped = clamped[i] || out.status.out_of_range[lane];
      r.non_finite = out.status.non_finite[lane];
      if (first->relaxation_) {
        tyres[i].transient_.set_relaxation_lengths(out.sigmax_m[lane], out.sigmay_m[lane]);
      }
    }
  }

  const mf::MfParameters<float>* params_{nullptr};
  mf::MfOptions options_{};
  bool relaxation_{false};
  bool restart_{true};
  mf::MfTransient<float> transient_{};
};

static_assert(BatchTyreChannel<MfTyreChannel>);

}  // namespace tread::node
