// src/node/mf_tyre_channel_fixed.hpp: the fixed-point channel has MfTyreChannel's semantics —
// the same clamping and flags for the same inputs, forces and moments within the fixed-point
// path's accuracy of the float channel's, with and without relaxation; an invalid input (the
// fixed-point NaN) gives non_finite.
#include "node/mf_tyre_channel_fixed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "node/mf_tyre_channel.hpp"

namespace tread::node {
namespace {

const mf::MfParameters<double>& book_tyre() {
  static const mf::MfParameters<double> p{};
  return p;
}

proto::WheelInputFixed to_fixed(const proto::WheelInput& in) {
  proto::WheelInputFixed f;
  f.kappa = Fixed64::from_double(in.kappa);
  f.alpha_rad = Fixed64::from_double(in.alpha_rad);
  f.gamma_rad = Fixed64::from_double(in.gamma_rad);
  f.fz_n = Fixed64::from_double(in.fz_n);
  f.vx_mps = Fixed64::from_double(in.vx_mps);
  f.omega_radps = Fixed64::from_double(in.omega_radps);
  f.omega_valid = in.omega_valid;
  return f;
}

// Inside the limits, at them, beyond each of them, a lifted wheel, the low-speed model.
std::array<proto::WheelInput, 9> inputs() {
  return {{{0.05F, 0.04F, 0.01F, 4200.0F, 22.0F, 0.0F, false},
           {-0.08F, -0.06F, -0.02F, 3100.0F, 22.5F, 0.0F, false},
           {0.0F, 0.12F, 0.0F, 5600.0F, 0.6F, 0.0F, false},
           {0.2F, -0.2F, 0.03F, 800.0F, 35.0F, 0.0F, false},
           {2.0F, 0.0F, 0.0F, 4000.0F, 20.0F, 0.0F, false},      // κ > KPUMAX
           {0.0F, -2.0F, 0.0F, 4000.0F, 20.0F, 0.0F, false},     // α < ALPMIN
           {0.0F, 0.05F, 0.9F, 4000.0F, 20.0F, 0.0F, false},     // γ > CAMMAX
           {0.05F, 0.05F, 0.0F, 25000.0F, 20.0F, 0.0F, false},   // Fz > FZMAX
           {0.05F, 0.05F, 0.0F, -300.0F, 20.0F, 0.0F, false}}};  // lifted
}

void expect_close(const TyreResultFixed& got, const TyreResult& want, std::size_t i) {
  const double force = std::max({std::fabs(want.fx_n), std::fabs(want.fy_n), 100.0F});
  const double moment =
      std::max({std::fabs(want.mz_nm), std::fabs(want.mx_nm), std::fabs(want.my_nm), 1.0F});
  // Float rounding and the fixed path's 0.1 % of each output's peak (mf_fixed_accuracy_test).
  EXPECT_NEAR(got.fx_n.to_double(), want.fx_n, 1e-3 * force) << i;
  EXPECT_NEAR(got.fy_n.to_double(), want.fy_n, 1e-3 * force) << i;
  EXPECT_NEAR(got.mz_nm.to_double(), want.mz_nm, 1e-3 * moment) << i;
  EXPECT_NEAR(got.mx_nm.to_double(), want.mx_nm, 1e-3 * moment) << i;
  EXPECT_NEAR(got.my_nm.to_double(), want.my_nm, 1e-3 * moment) << i;
  EXPECT_NEAR(got.rl_m.to_double(), want.rl_m, 1e-5) << i;
  EXPECT_EQ(got.clamped, want.clamped) << i;
  EXPECT_EQ(got.non_finite, want.non_finite) << i;
}

TEST(MfTyreChannelFixed, SameClampingFlagsAndForcesAsTheFloatChannel) {
  const mf::MfOptions options = mf::options_from_use_mode(111).value;
  const auto pf = mf::convert_parameters<float>(book_tyre());
  const auto px = mf::to_fixed_parameters(book_tyre());
  MfTyreChannel f(pf, options);
  MfTyreChannelFixed x(px, options);
  const auto in = inputs();
  for (std::size_t i = 0; i < in.size(); ++i) {
    const TyreResult want = f.evaluate(in[i], 0.0F);
    const TyreResultFixed got = x.evaluate(to_fixed(in[i]), Fixed64(0.0));
    expect_close(got, want, i);
  }
  // The limits flag: beyond each limit, and only there.
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_FALSE(x.evaluate(to_fixed(in[i]), Fixed64(0.0)).clamped) << i;
  }
  for (std::size_t i = 4; i < in.size(); ++i) {
    EXPECT_TRUE(x.evaluate(to_fixed(in[i]), Fixed64(0.0)).clamped) << i;
  }
}

TEST(MfTyreChannelFixed, RelaxationFollowsTheFloatChannelAndRestartsOnReset) {
  const mf::MfOptions options = mf::options_from_use_mode(111).value;
  const auto pf = mf::convert_parameters<float>(book_tyre());
  const auto px = mf::to_fixed_parameters(book_tyre());
  MfTyreChannel f(pf, options, true);
  MfTyreChannelFixed x(px, options, true);
  const auto in = inputs();
  // A slip step held for 20 ms at 1 kHz, then a reset: the lag starts from the new slips.
  for (int k = 0; k < 20; ++k) {
    const std::size_t i = k < 5 ? 0 : 1;
    const TyreResult want = f.evaluate(in[i], k == 0 ? 0.0F : 1e-3F);
    const TyreResultFixed got = x.evaluate(to_fixed(in[i]), k == 0 ? Fixed64(0.0) : Fixed64(1e-3));
    expect_close(got, want, static_cast<std::size_t>(k));
    EXPECT_NEAR(x.transient().kappa().to_double(), f.transient().kappa(), 1e-5) << k;
    EXPECT_NEAR(x.transient().alpha_rad().to_double(), f.transient().alpha_rad(), 1e-5) << k;
  }
  x.reset();
  static_cast<void>(x.evaluate(to_fixed(in[3]), Fixed64(1e-3)));
  EXPECT_EQ(x.transient().kappa(), Fixed64::from_double(in[3].kappa));
}

TEST(MfTyreChannelFixed, AnInvalidInputIsNonFiniteAndAnEmptyChannelGivesZeros) {
  const mf::MfOptions options = mf::options_from_use_mode(111).value;
  const auto px = mf::to_fixed_parameters(book_tyre());
  MfTyreChannelFixed x(px, options);
  proto::WheelInputFixed in = to_fixed(inputs()[0]);
  in.kappa = Fixed64::invalid();
  EXPECT_TRUE(x.evaluate(in, Fixed64(0.0)).non_finite);
  MfTyreChannelFixed empty;
  const TyreResultFixed r = empty.evaluate(to_fixed(inputs()[0]), Fixed64(0.0));
  EXPECT_EQ(r.fx_n, Fixed64(0.0));
  EXPECT_FALSE(r.clamped || r.non_finite);
}

}  // namespace
}  // namespace tread::node
