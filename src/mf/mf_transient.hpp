#pragma once
// First-order transient slip stage for the 1 kHz loop (optional, allocation-free): the slips the
// Magic Formula sees lag the kinematic slips with the relaxation lengths of the tyre,
//   dκ'/dt = |Vx|/σκ · (κ − κ'),   dα'/dt = |Vx|/σα · (α − α'),
// so the time constant of a step is σ/|Vx| (σκ = sigmax, σα = sigmay as evaluate() returns them:
// MF 6.x |Kxk/Cx|, |Kya/Cy|; MF 5.2/PAC2002 from PTX1…3, PTY1/2 and LSGKP/LSGAL).
// step(dt) integrates exactly over the step (κ' += (κ − κ')·(1 − e^(−|Vx|·dt/σ))), so it is
// stable for any dt. The relaxation lengths are those of the previous step's load (one sample of
// lag, 1 ms at 1 kHz). With |Vx| = 0 the transient slips hold their value.

#include "mf/mf_evaluate.hpp"

namespace tread::mf {

template <typename T>
class MfTransient {
 public:
  /// Set the transient slips (e.g. to the current kinematic slips: no transient).
  void reset(const T& kappa, const T& alpha_rad) {
    kappa_ = kappa;
    alpha_ = alpha_rad;
    have_sigma_ = false;
  }

  const T& kappa() const { return kappa_; }
  const T& alpha_rad() const { return alpha_; }

  /// Advance by dt_s with the kinematic slips of `input`, then evaluate the Magic Formula with
  /// the transient slips. Needs options.extras (for the relaxation lengths); it is forced on.
  MfOutput<T> step(const MfParameters<T>& params, const MfInput<T>& input, MfOptions options,
                   const T& dt_s) {
    using std::abs;
    using std::exp;
    options.extras = true;
    if (!have_sigma_) {
      // First step: relaxation lengths at this load.
      MfInput<T> probe = input;
      probe.kappa = kappa_;
      probe.alpha_rad = alpha_;
      const MfOutput<T> out0 = evaluate(params, probe, options);
      sigma_kappa_ = out0.sigmax_m;
      sigma_alpha_ = out0.sigmay_m;
      have_sigma_ = true;
    }
    const T distance = abs(input.vx_mps) * (dt_s > T(0) ? dt_s : T(0));
    kappa_ = kappa_ + (input.kappa - kappa_) * blend(distance, sigma_kappa_);
    alpha_ = alpha_ + (input.alpha_rad - alpha_) * blend(distance, sigma_alpha_);
    MfInput<T> relaxed = input;
    relaxed.kappa = kappa_;
    relaxed.alpha_rad = alpha_;
    const MfOutput<T> out = evaluate(params, relaxed, options);
    sigma_kappa_ = out.sigmax_m;
    sigma_alpha_ = out.sigmay_m;
    return out;
  }

 private:
  /// 1 − e^(−s/σ); σ below 1 mm (or zero load) means no lag.
  static T blend(const T& distance, const T& sigma) {
    using std::exp;
    if (!(sigma > T(1e-3))) return T(1);
    return T(1) - exp(-distance / sigma);
  }

  T kappa_ = T(0);
  T alpha_ = T(0);
  T sigma_kappa_ = T(0);
  T sigma_alpha_ = T(0);
  bool have_sigma_ = false;
};

}  // namespace tread::mf
