#pragma once
// The arithmetic the image runs, chosen at build time (CMake option TREAD_FIRMWARE_FIXED):
// - float (Cortex-M4F, single-precision FPU): MfTyreChannel on the float tyre header, the flashed
//   float contact table; its answers match the host's float replay within one quantisation step of
//   the protocol (floating-point contraction and library functions differ between the compilers);
// - fixed point (FPU-less Cortex-M0+/M3): MfTyreChannelFixed on the Q31.32 tyre header
//   (tread_tir_header --mf --fixed), the flashed integer contact table, the codec's integer signal
//   route; no float anywhere in the image (scripts/check-no-softfloat.sh), so its answers are the
//   host's `tread node --fixed` replay bit for bit.

#include <cstdint>

#include "lut/tread_lut.hpp"
#include "mf/mf_options.hpp"
#include "node/contact_table_channel.hpp"
#include "node/contact_table_channel_fixed.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/mf_tyre_channel_fixed.hpp"

#if TREAD_FIRMWARE_FIXED
#include "generated/tyre_mf61_fixed.hpp"
#else
#include "generated/tyre_mf61.hpp"
#endif

namespace tread::firmware {

#if TREAD_FIRMWARE_FIXED
inline constexpr bool kFixedPoint = true;
inline constexpr const mf::MfParameters<fixed::Fixed64>& kTyreParameters = kTyreFixed;
using TyreChannel = node::MfTyreChannelFixed;
using ContactChannel = node::ContactTableChannelFixed;
inline const rail::ContactTableQ& contact_table() noexcept {
  return lut::contact_pairs()[0].q;
}
#else
inline constexpr bool kFixedPoint = false;
inline constexpr const mf::MfParameters<float>& kTyreParameters = kTyre;
using TyreChannel = node::MfTyreChannel;
using ContactChannel = node::ContactTableChannel;
inline const rail::ContactTableF32& contact_table() noexcept {
  return lut::contact_pairs()[0].f32;
}
#endif

/// The tyre model's options: MFeval useMode 111, Rl an output (as `tread node` runs it).
inline mf::MfOptions tyre_options() noexcept {
  mf::MfOptions o = mf::options_from_use_mode(111).value;
  o.extras = true;
  return o;
}

/// How far a transmitted signal may be from the host's, in raw steps of the protocol: none on
/// the integer path, one (the quantisation step) on the float path.
inline constexpr std::int64_t kMaxRawSteps = kFixedPoint ? 0 : 1;

}  // namespace tread::firmware
