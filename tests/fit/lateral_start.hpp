#pragma once
// The neutral start of the pure-lateral fit tests and benchmark: the file's own non-lateral data
// (FNOMIN, scalings, ...) with the 13 fitted γ-free lateral coefficients at the book's defaults.

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

}  // namespace tread::testing
