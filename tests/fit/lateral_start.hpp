#pragma once
// What the pure-lateral fit tests and benchmark share: the pure lateral force, and the neutral
// start: the file's own non-lateral data (FNOMIN, scalings, ...) with the 13 fitted γ-free lateral
// coefficients at the book's defaults.

#include "mf/mf_evaluate.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::testing {

inline mf::MfParameters<double> book_lateral_start(const mf::MfParameters<double>& truth) {
  mf::MfParameters<double> start = truth;
  const mf::MfParameters<double> book;
  start.pcy1 = book.pcy1;
  start.pdy1 = book.pdy1;
  start.pdy2 = book.pdy2;
  start.pey1 = book.pey1;
  start.pey2 = book.pey2;
  start.pey3 = book.pey3;
  start.pky1 = book.pky1;
  start.pky2 = book.pky2;
  start.pky4 = book.pky4;
  start.phy1 = book.phy1;
  start.phy2 = book.phy2;
  start.pvy1 = book.pvy1;
  start.pvy2 = book.pvy2;
  return start;
}

/// Pure lateral force Fy0(alpha) at load fz (the fit's own conditions: uncombined, no extras).
inline double pure_fy_n(const mf::MfParameters<double>& p, double fz_n, double alpha_rad) {
  mf::MfInput<double> in;
  in.fz_n = fz_n;
  in.alpha_rad = alpha_rad;
  in.vx_mps = 16.6;
  mf::MfOptions o;
  o.combined = false;
  o.extras = false;
  return mf::evaluate(p, in, o).fy_n;
}

}  // namespace tread::testing
