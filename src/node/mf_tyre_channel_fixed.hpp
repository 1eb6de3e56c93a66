#pragma once
// A road-wheel channel on the Magic Formula in fixed point (mf::evaluate<Fixed64>, integer
// arithmetic only), for cores without an FPU: the same semantics as MfTyreChannel (float) — the
// inputs clamped to the property file's limits (FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX,
// CAMMIN/CAMMAX) and flagged, Fz < 0 taken as 0 and flagged, an invalid model output (Q31.32
// overflow, an invalid input: the fixed-point NaN) reported as non_finite, optional first-order
// relaxation restarted by reset() — on Fixed64 inputs and results, so a caller that decodes the
// CAN signals with proto::decode_signal_fixed and encodes with encode_signal_fixed never touches
// a float. One wheel at a time (no vector lanes on the cores it is for). A channel of the node
// (channels.hpp) with Scalar = Fixed64.

#include "core/status.hpp"
#include "fixed/fixed64.hpp"
#include "mf/mf_fixed.hpp"
#include "mf/mf_transient.hpp"
#include "node/channels.hpp"
#include "proto/data_model.hpp"

namespace tread::node {

using fixed::Fixed64;

class MfTyreChannelFixed {
 public:
  using Scalar = Fixed64;

  MfTyreChannelFixed() = default;
  /// `params` (e.g. a generated header's constants) must outlive the channel. `relaxation`:
  /// first-order transient slips. Without relaxation only Rl of the extras is evaluated.
  MfTyreChannelFixed(const mf::MfParameters<Fixed64>& params, const mf::MfOptions& options,
                     bool relaxation = false) noexcept
      : params_(&params), options_(options), relaxation_(relaxation) {
    options_.extras = true;
    options_.extras_loaded_radius_only = !relaxation;
  }

  /// `dt_s`: the time since the previous evaluation (0 on the first one).
  TyreResultFixed evaluate(const proto::WheelInputFixed& in, Fixed64 dt_s) noexcept {
    TyreResultFixed result;
    if (params_ == nullptr) {
      return result;
    }
    const mf::MfInput<Fixed64> input = limited(in, result.clamped);
    mf::MfOutput<Fixed64> out;
    if (relaxation_) {
      if (restart_) {
        transient_.reset(input.kappa, input.alpha_rad);
        restart_ = false;
      }
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

  /// Restarts the relaxation from the next received slips.
  void reset() noexcept { restart_ = true; }

  /// The transient slips (the received ones without relaxation).
  [[nodiscard]] const mf::MfTransient<Fixed64>& transient() const noexcept { return transient_; }

 private:
  /// The input clamped to the file's limits; `clamped` set when a limit applied. An invalid
  /// input stays invalid (every comparison with it is false), as a NaN does in MfTyreChannel.
  mf::MfInput<Fixed64> limited(const proto::WheelInputFixed& in, bool& clamped) const noexcept {
    const mf::MfParameters<Fixed64>& p = *params_;
    const auto clamp = [&clamped](Fixed64 v, Fixed64 lo, Fixed64 hi) {
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
    mf::MfInput<Fixed64> input;
    input.fz_n = clamp(in.fz_n, Fixed64(0.0), p.fzmax_n);
    input.kappa = clamp(in.kappa, p.kpumin, p.kpumax);
    input.alpha_rad = clamp(in.alpha_rad, p.alpmin_rad, p.alpmax_rad);
    input.gamma_rad = clamp(in.gamma_rad, p.cammin_rad, p.cammax_rad);
    input.vx_mps = in.vx_mps;
    return input;
  }

  const mf::MfParameters<Fixed64>* params_{nullptr};
  mf::MfOptions options_{};
  bool relaxation_{false};
  bool restart_{true};
  mf::MfTransient<Fixed64> transient_{};
};

static_assert(TyreChannel<MfTyreChannelFixed>);

}  // namespace tread::node
