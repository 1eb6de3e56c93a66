#pragma once
// A road-wheel channel on the Magic Formula core (float): clamps the inputs to the property file's
// limits (FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX) and flags it, then evaluates.
// Fz < 0 is taken as 0 (lifted wheel: zero forces) and flagged.

#include "mf/mf_evaluate.hpp"
#include "node/channels.hpp"

namespace tread::node {

class MfTyreChannel {
 public:
  MfTyreChannel() = default;
  /// `params` must outlive the channel.
  /// The node sends Rl alone of the extras: the contact patch and relaxation lengths are skipped.
  MfTyreChannel(const mf::MfParameters<float>& params, const mf::MfOptions& options) noexcept
      : params_(&params), options_(options) {
    options_.extras_loaded_radius_only = true;
  }

  TyreResult evaluate(const proto::WheelInput& in, float /*dt_s*/) noexcept {
    TyreResult result;
    if (params_ == nullptr) {
      return result;
    }
    const mf::MfParameters<float>& p = *params_;
    bool clamped = false;
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
    const mf::MfOutput<float> out = mf::evaluate(p, input, options_);
    result.fx_n = out.fx_n;
    result.fy_n = out.fy_n;
    result.mz_nm = out.mz_nm;
    result.mx_nm = out.mx_nm;
    result.my_nm = out.my_nm;
    result.rl_m = out.rl_m;
    result.clamped = clamped || out.status != Status::ok;
    return result;
  }

  void reset() noexcept {}

 private:
  const mf::MfParameters<float>* params_{nullptr};
  mf::MfOptions options_{};
};

static_assert(TyreChannel<MfTyreChannel>);

}  // namespace tread::node
