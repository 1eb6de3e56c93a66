#pragma once
// Left/right mirroring of PAC89/PAC94 coefficient sets (TYRESIDE): the Adams Tire help ("Left and
// Right Side Tires") lists the parameters whose sign switches when the characteristics are
// mirrored about α = 0:
//   PAC89: A9, A10, A12, A13, C12, C13, C16, C17
//   PAC94: A8, A9, A11, A12, A17, C11, C12, C14, C15, C20
// The mirrored tyre satisfies Fy'(κ, α, γ) = −Fy(κ, −α, −γ), Mz' likewise, Fx'(κ, α, γ) = Fx(κ, −α,
// −γ) (tests/pac/pac_mirror_test.cpp checks exactly this for random coefficients, which also
// cross-checks the PAC94 equation layout against the Adams list).

#include "pac/pac_params.hpp"

namespace tread::pac {

template <typename T>
PacParams<T> mirror_pac89(PacParams<T> p) {
  for (const int i : {9, 10, 12, 13})
    p.a[static_cast<unsigned>(i)] = -p.a[static_cast<unsigned>(i)];
  for (const int i : {12, 13, 16, 17})
    p.c[static_cast<unsigned>(i)] = -p.c[static_cast<unsigned>(i)];
  return p;
}

template <typename T>
PacParams<T> mirror_pac94(PacParams<T> p) {
  for (const int i : {8, 9, 11, 12, 17})
    p.a[static_cast<unsigned>(i)] = -p.a[static_cast<unsigned>(i)];
  for (const int i : {11, 12, 14, 15, 20})
    p.c[static_cast<unsigned>(i)] = -p.c[static_cast<unsigned>(i)];
  return p;
}

}  // namespace tread::pac
