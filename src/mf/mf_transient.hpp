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

  /// The relaxation lengths the next advance() uses: known after the first step.
  bool has_relaxation_lengths() const { return have_sigma_; }
  void set_relaxation_lengths(const T& sigmax_m, const T& sigmay_m) {
    sigma_kappa_ = sigmax_m;
    sigma_alpha_ = sigmay_m;
    have_sigma_ = true;
  }

  /// Advances the transient slips by dt_s toward `input`'s kinematic slips (with the relaxation
  /// lengths set before) and returns `input` with the transient slips. step() is: relaxation
  /// lengths if none yet, advance, evaluate, relaxation lengths from that evaluation; callers that
  /// evaluate elsewhere (four wheels on lanes) do the same in pieces.
  MfInput<T> advance(const MfInput<T>& input, const T& dt_s) {
    using std::abs;
    const T distance = abs(input.vx_mps) * (dt_s > T(0) ? dt_s : T(0));
    kappa_ = kappa_ + (input.kappa - kappa_) * blend(distance, sigma_kappa_);
    alpha_ = alpha_ + (input.alpha_rad - alpha_) * blend(distance, sigma_alpha_);
    MfInput<T> relaxed = input;
    relaxed.kappa = kappa_;
    relaxed.alpha_rad = alpha_;
    return relaxed;
  }

  /// The input at the current transient slips (what the first step takes its relaxation lengths
  /// from).
  MfInput<T> probe(const MfInput<T>& input) const {
    MfInput<T> p = input;
    p.kappa = kappa_;
    p.alpha_rad = alpha_;
    return p;
  }

  /// Advance by dt_s with the kinematic slips of `input`, then evaluate the Magic Formula with
  /// the transient slips. Needs options.extras (for the relaxation lengths); it is forced on.
  MfOutput<T> step(const MfParameters<T>& params, const MfInput<T>& input, MfOptions options,
                   const T& dt_s) {
    options.extras = true;
    options.extras_loaded_radius_only = false;  // the relaxation lengths are needed
    if (!have_sigma_) {
      // First step: relaxation lengths at this load.
      const MfOutput<T> out0 = evaluate(params, probe(input), options);
      set_relaxation_lengths(out0.sigmax_m, out0.sigmay_m);
    }
    const MfOutput<T> out = evaluate(params, advance(input, dt_s), options);
    set_relaxation_lengths(out.sigmax_m, out.sigmay_m);
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
