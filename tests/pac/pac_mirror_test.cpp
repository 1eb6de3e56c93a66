// Mirroring (TYRESIDE) with random coefficient sets: every shift and asymmetry coefficient random,
// the mirrored set must give Fy'(α, γ) = −Fy(−α, −γ), Mz'(α, γ) = −Mz(−α, −γ) and unchanged Fx, in
// pure and combined slip. Because the parameter lists come from the Adams help, this also checks
// that our PAC89/PAC94 shift and curvature terms have the layout Adams uses.
#include "pac/pac_mirror.hpp"

#include <gtest/gtest.h>

#include <random>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "pac_test_sets.hpp"

namespace {

using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;

PacParams<double> random_set(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto p = tread::pac::testing::symmetric_set<double>();
  // Shifts and asymmetries (PAC89 and PAC94 indices; each model ignores what it does not use).
  for (const int i : {8, 9, 10}) p.a[static_cast<unsigned>(i)] = 0.3 * u(rng);
  for (const int i : {11, 12, 13, 14}) p.a[static_cast<unsigned>(i)] = 20.0 * u(rng);
  p.a[5] = 0.01 * u(rng);
  p.a[15] = 0.005 * u(rng);
  p.a[16] = 0.05 * u(rng);
  p.a[17] = 0.3 * u(rng);
  for (const int i : {11, 12, 13}) p.c[static_cast<unsigned>(i)] = 0.3 * u(rng);
  for (const int i : {14, 15, 16, 17}) p.c[static_cast<unsigned>(i)] = 2.0 * u(rng);
  p.c[6] = 0.01 * u(rng);
  p.c[10] = 0.01 * u(rng);
  p.c[18] = 0.005 * u(rng);
  p.c[19] = 0.05 * u(rng);
  p.c[20] = 0.3 * u(rng);
  p.b[9] = 0.05 * u(rng);
  p.b[10] = 0.5 * u(rng);
  return p;
}

template <typename Eval, typename Mirror>
void check(Eval eval, Mirror mirror) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> fz(500.0, 9000.0), k(-0.4, 0.4), a(-0.3, 0.3),
      g(-0.08, 0.08);
  for (int set = 0; set < 50; ++set) {
    const auto p = random_set(rng);
    const auto m = mirror(p);
    for (int i = 0; i < 200; ++i) {
      const PacInput<double> in{fz(rng), k(rng), a(rng), g(rng)};
      const PacInput<double> flipped{in.fz_n, in.kappa, -in.alpha_rad, -in.gamma_rad};
      for (const auto slip : {Slip::kPure, Slip::kCombined}) {
        const auto om = eval(m, in, slip);
        const auto o = eval(p, flipped, slip);
        EXPECT_NEAR(om.fy_n, -o.fy_n, 1e-9 * (1 + std::abs(o.fy_n)));
        EXPECT_NEAR(om.mz_nm, -o.mz_nm, 1e-9 * (1 + std::abs(o.mz_nm)));
        EXPECT_NEAR(om.fx_n, o.fx_n, 1e-9 * (1 + std::abs(o.fx_n)));
      }
    }
  }
}

TEST(PacMirror, Pac89MirrorsAboutZeroSlipAngle) {
  check([](const auto& p, const auto& in, Slip s) { return tread::pac::pac89_eval(p, in, s); },
        [](const auto& p) { return tread::pac::mirror_pac89(p); });
}

TEST(PacMirror, Pac94MirrorsAboutZeroSlipAngle) {
  check([](const auto& p, const auto& in, Slip s) { return tread::pac::pac94_eval(p, in, s); },
        [](const auto& p) { return tread::pac::mirror_pac94(p); });
}

TEST(PacMirror, MirrorTwiceIsIdentity) {
  std::mt19937_64 rng(3);
  const auto p = random_set(rng);
  EXPECT_EQ(tread::pac::mirror_pac89(tread::pac::mirror_pac89(p)).a, p.a);
  EXPECT_EQ(tread::pac::mirror_pac94(tread::pac::mirror_pac94(p)).c, p.c);
  EXPECT_NE(tread::pac::mirror_pac94(p).a, p.a);
}

}  // namespace
