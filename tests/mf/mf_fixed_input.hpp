#pragma once
// An input in fixed point (Q31.32, each value rounded to nearest): what the fixed path sees of a
// double input. Shared by the tests that compare the fixed path with double.
#include "fixed/fixed64.hpp"
#include "mf/mf_types.hpp"

namespace tread::testing {

inline mf::MfInput<fixed::Fixed64> to_fixed(const mf::MfInput<double>& in) {
  using fixed::Fixed64;
  mf::MfInput<Fixed64> f;
  f.fz_n = Fixed64::from_double(in.fz_n);
  f.kappa = Fixed64::from_double(in.kappa);
  f.alpha_rad = Fixed64::from_double(in.alpha_rad);
  f.gamma_rad = Fixed64::from_double(in.gamma_rad);
  f.vx_mps = Fixed64::from_double(in.vx_mps);
  f.phit_1pm = Fixed64::from_double(in.phit_1pm);
  f.p_pa = Fixed64::from_double(in.p_pa);
  return f;
}

}  // namespace tread::testing
