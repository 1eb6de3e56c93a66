// src/node/mf_tyre_channel.hpp: the node's due wheels evaluated together (four float lanes where
// the target has them) give what each channel's own evaluate() gives, wheel by wheel, within float
// rounding; wheels not due are left alone; clamping is flagged per wheel; channels on different
// tyres fall back to one by one.
#include "node/mf_tyre_channel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tread::node {
namespace {

const mf::MfParameters<float>& book_tyre() {
  static const mf::MfParameters<float> p =
      mf::convert_parameters<float>(mf::MfParameters<double>{});
  return p;
}

/// The book tyre with lateral offsets, so that mounting it on the other side changes its forces.
const mf::MfParameters<float>& asymmetric_tyre() {
  static const mf::MfParameters<float> p = [] {
    mf::MfParameters<double> d;
    d.phy1 = 0.004;
    d.pvy1 = 0.04;
    d.qhz1 = 0.003;
    return mf::convert_parameters<float>(d);
  }();
  return p;
}

std::array<proto::WheelInput, 4> driving_inputs() {
  std::array<proto::WheelInput, 4> in{};
  in[0] = {0.05F, 0.04F, 0.01F, 4200.0F, 22.0F, 0.0F, false};
  in[1] = {-0.08F, -0.06F, -0.02F, 3100.0F, 22.5F, 0.0F, false};
  in[2] = {0.0F, 0.12F, 0.0F, 5600.0F, 0.6F, 0.0F, false};  // below VXLOW: low-speed model
  in[3] = {0.2F, -0.2F, 0.03F, 800.0F, 35.0F, 0.0F, false};
  return in;
}

void expect_close(const TyreResult& got, const TyreResult& want, int wheel) {
  const auto near = [](float a, float b, float scale) {
    return std::fabs(a - b) <= 2e-5F * std::max(scale, 1.0F);
  };
  const float force = std::max({std::fabs(want.fx_n), std::fabs(want.fy_n), 100.0F});
  const float moment =
      std::max({std::fabs(want.mz_nm), std::fabs(want.mx_nm), std::fabs(want.my_nm), 1.0F});
  EXPECT_TRUE(near(got.fx_n, want.fx_n, force)) << wheel << ": " << got.fx_n << " vs " << want.fx_n;
  EXPECT_TRUE(near(got.fy_n, want.fy_n, force)) << wheel << ": " << got.fy_n << " vs " << want.fy_n;
  EXPECT_TRUE(near(got.mz_nm, want.mz_nm, moment)) << wheel << ": " << got.mz_nm;
  EXPECT_TRUE(near(got.mx_nm, want.mx_nm, moment)) << wheel << ": " << got.mx_nm;
  EXPECT_TRUE(near(got.my_nm, want.my_nm, moment)) << wheel << ": " << got.my_nm;
  EXPECT_TRUE(near(got.rl_m, want.rl_m, 0.3F)) << wheel << ": " << got.rl_m << " vs " << want.rl_m;
  EXPECT_EQ(got.clamped, want.clamped) << wheel;
}

TEST(MfTyreChannel, DueWheelsTogetherEqualEachWheelAlone) {
  mf::MfOptions left = mf::options_from_use_mode(111).value;
  left.side = mf::MountedSide::left;
  mf::MfOptions right = left;
  right.side = mf::MountedSide::right;  // mirrored: the book tyre is measured as a left one
  std::array<MfTyreChannel, 4> tyres{
      MfTyreChannel(asymmetric_tyre(), left), MfTyreChannel(asymmetric_tyre(), right),
      MfTyreChannel(asymmetric_tyre(), left), MfTyreChannel(asymmetric_tyre(), right)};
  auto inputs = driving_inputs();
  inputs[3].alpha_rad = 2.0F;  // beyond ALPMAX: clamped and flagged, this wheel only
  for (std::uint8_t due : {std::uint8_t{0x0F}, std::uint8_t{0x05}, std::uint8_t{0x0A},
                           std::uint8_t{0x0E}, std::uint8_t{0x01}}) {
    std::array<TyreResult, 4> together{};
    MfTyreChannel::evaluate_wheels(tyres, inputs, due, 0.001F, together);
    for (std::size_t i = 0; i < 4; ++i) {
      if (((static_cast<unsigned>(due) >> i) & 1U) == 0U) {
        EXPECT_EQ(together[i].fx_n, 0.0F) << "wheel " << i << " is not due";
        EXPECT_EQ(together[i].rl_m, 0.0F) << "wheel " << i << " is not due";
        continue;
      }
      const TyreResult alone = tyres[i].evaluate(inputs[i], 0.001F);
      expect_close(together[i], alone, static_cast<int>(i));
      EXPECT_NE(alone.fy_n, 0.0F);
    }
  }
  std::array<TyreResult, 4> r{};
  MfTyreChannel::evaluate_wheels(tyres, inputs, 0x0F, 0.001F, r);
  EXPECT_FALSE(r[0].clamped || r[1].clamped || r[2].clamped);
  EXPECT_TRUE(r[3].clamped);
  // Mirroring took effect: the same input on a left and a right wheel of this asymmetric tyre
  // gives different lateral forces (each equal to its own scalar evaluation above).
  inputs[1] = inputs[0];
  MfTyreChannel::evaluate_wheels(tyres, inputs, 0x03, 0.001F, r);
  EXPECT_GT(std::fabs(r[1].fy_n - r[0].fy_n), 10.0F);
  expect_close(r[1], tyres[1].evaluate(inputs[1], 0.001F), 1);
}

TEST(MfTyreChannel, WheelsOnDifferentTyresAreEvaluatedOneByOne) {
  mf::MfParameters<double> other_double;
  other_double.pdx1 = 1.4;
  other_double.pdy1 = 1.2;
  const mf::MfParameters<float> other = mf::convert_parameters<float>(other_double);
  const mf::MfOptions o = mf::options_from_use_mode(111).value;
  std::array<MfTyreChannel, 4> tyres{MfTyreChannel(book_tyre(), o), MfTyreChannel(other, o),
                                     MfTyreChannel(book_tyre(), o), MfTyreChannel(other, o)};
  const auto inputs = driving_inputs();
  std::array<TyreResult, 4> together{};
  MfTyreChannel::evaluate_wheels(tyres, inputs, 0x0F, 0.001F, together);
  for (std::size_t i = 0; i < 4; ++i) {
    const TyreResult alone = tyres[i].evaluate(inputs[i], 0.001F);
    EXPECT_EQ(together[i].fx_n, alone.fx_n) << i;  // the scalar path itself: bit for bit
    EXPECT_EQ(together[i].fy_n, alone.fy_n) << i;
    EXPECT_EQ(together[i].mz_nm, alone.mz_nm) << i;
  }
  EXPECT_NE(together[0].fy_n, together[1].fy_n);
}

TEST(MfTyreChannel, LiftedAndStandingWheelsGiveFiniteZeroForces) {
  const mf::MfOptions o = mf::options_from_use_mode(111).value;
  std::array<MfTyreChannel, 4> tyres{MfTyreChannel(book_tyre(), o), MfTyreChannel(book_tyre(), o),
                                     MfTyreChannel(book_tyre(), o), MfTyreChannel(book_tyre(), o)};
  auto inputs = driving_inputs();
  inputs[0].fz_n = -50.0F;  // lifted: clamped to 0 and flagged
  inputs[1].vx_mps = 0.0F;  // standing
  std::array<TyreResult, 4> r{};
  MfTyreChannel::evaluate_wheels(tyres, inputs, 0x0F, 0.001F, r);
  EXPECT_EQ(r[0].fx_n, 0.0F);
  EXPECT_EQ(r[0].fy_n, 0.0F);
  EXPECT_TRUE(r[0].clamped);
  for (const TyreResult& w : r) {
    for (float v : {w.fx_n, w.fy_n, w.mz_nm, w.mx_nm, w.my_nm, w.rl_m})
      EXPECT_TRUE(std::isfinite(v));
  }
  expect_close(r[1], tyres[1].evaluate(inputs[1], 0.001F), 1);
}

TEST(MfTyreChannel, DefectiveTyreDataIsReportedNonFiniteNeverNan) {
  // VERTICAL_STIFFNESS = 0 (a defective file): the radii come out non-finite.
  mf::MfParameters<double> d;
  d.vertical_stiffness_npm = 0.0;
  const mf::MfParameters<float> defective = mf::convert_parameters<float>(d);
  for (const bool relaxation : {false, true}) {
    const mf::MfOptions o = mf::options_from_use_mode(111).value;
    std::array<MfTyreChannel, 4> tyres{
        MfTyreChannel(defective, o, relaxation), MfTyreChannel(defective, o, relaxation),
        MfTyreChannel(defective, o, relaxation), MfTyreChannel(defective, o, relaxation)};
    const auto inputs = driving_inputs();
    std::array<TyreResult, 4> together{};
    MfTyreChannel::evaluate_wheels(tyres, inputs, 0x0F, 0.001F, together);
    for (std::size_t i = 0; i < 4; ++i) {
      const TyreResult alone = tyres[i].evaluate(inputs[i], 0.001F);
      for (const TyreResult& r : {together[i], alone}) {
        EXPECT_TRUE(r.non_finite) << i << " relaxation " << relaxation;
        for (const float v : {r.fx_n, r.fy_n, r.mz_nm, r.mx_nm, r.my_nm, r.rl_m}) {
          EXPECT_TRUE(std::isfinite(v)) << i;
        }
      }
    }
  }
  // The sound tyre is not flagged.
  const mf::MfOptions o = mf::options_from_use_mode(111).value;
  MfTyreChannel sound(book_tyre(), o);
  EXPECT_FALSE(sound.evaluate(driving_inputs()[0], 0.001F).non_finite);
}

TEST(MfTyreChannel, RelaxationLagsASlipStepWithTheRelaxationLength) {
  // A step in α at 20 m/s: the lateral force rises as 1 − e^(−Vx·t/σα) (σα from the tyre), equal
  // four at a time and one by one; reset() restarts from the received slips (no lag).
  const mf::MfOptions o = mf::options_from_use_mode(111).value;
  std::array<MfTyreChannel, 4> together;
  std::array<MfTyreChannel, 4> alone;
  for (std::size_t i = 0; i < 4; ++i) {
    together[i] = MfTyreChannel(book_tyre(), o, true);
    alone[i] = MfTyreChannel(book_tyre(), o, true);
  }
  std::array<proto::WheelInput, 4> in{};
  for (auto& w : in) w = {0.0F, 0.0F, 0.0F, 4000.0F, 20.0F, 0.0F, false};
  std::array<TyreResult, 4> r{};
  const float dt_s = 0.001F;
  MfTyreChannel::evaluate_wheels(together, in, 0x0F, dt_s, r);  // settle at α = 0
  for (std::size_t i = 0; i < 4; ++i) static_cast<void>(alone[i].evaluate(in[i], dt_s));
  for (std::size_t i = 0; i < 4; ++i) in[i].alpha_rad = 0.02F + 0.01F * static_cast<float>(i);

  // Steady state of the step (no relaxation) and σα at this load.
  MfTyreChannel steady(book_tyre(), o);
  mf::MfOptions full = o;
  full.extras = true;
  const mf::MfOutput<float> ref = mf::evaluate(
      book_tyre(), mf::MfInput<float>{4000.0F, 0.0F, 0.02F, 0.0F, 20.0F, 0.0F, 0.0F}, full);
  ASSERT_GT(ref.sigmay_m, 0.05F);
  const float tau_s = ref.sigmay_m / 20.0F;
  const int steps = static_cast<int>(std::lround(tau_s / dt_s));  // one time constant
  float fy_after_tau = 0.0F;
  for (int k = 1; k <= steps; ++k) {
    MfTyreChannel::evaluate_wheels(together, in, 0x0F, dt_s, r);
    for (std::size_t i = 0; i < 4; ++i) {
      expect_close(r[i], alone[i].evaluate(in[i], dt_s), static_cast<int>(i));
    }
    if (k == 1) {
      EXPECT_LT(std::fabs(r[0].fy_n), 0.1F * std::fabs(ref.fy_n));
    }
    fy_after_tau = r[0].fy_n;
  }
  // After one time constant the transient slip is 1 − 1/e of the step (within a step's worth).
  const float alpha_after = together[0].transient().alpha_rad();
  EXPECT_NEAR(alpha_after / 0.02F, 1.0F - std::exp(-1.0F), 0.02F);
  EXPECT_NEAR(fy_after_tau / steady.evaluate(in[0], dt_s).fy_n, 1.0F - std::exp(-1.0F), 0.05F);

  for (auto& t : together) t.reset();
  MfTyreChannel::evaluate_wheels(together, in, 0x0F, dt_s, r);
  EXPECT_FLOAT_EQ(together[0].transient().alpha_rad(), in[0].alpha_rad);  // restarted: no lag
  expect_close(r[0], steady.evaluate(in[0], dt_s), 0);
}

}  // namespace
}  // namespace tread::node
