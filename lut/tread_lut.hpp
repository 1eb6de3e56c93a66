#pragma once
// The lookup tables an ECU build flashes: wheel rolling-radius tables r(y) = r0 + z(y) and
// wheel–rail contact tables, generated at build time by tread_lut_gen from the double definitions
// (sim/profile, sim/contact) into constexpr arrays, float32 and fixed point. Never edited by hand.
// Which profiles and pairs go in is chosen by the CMake cache variables TREAD_LUT_PROFILES and
// TREAD_LUT_CONTACT_PAIRS.

#include <span>

#include "rail/contact_lookup.hpp"

namespace tread::lut {

struct ProfileTable {
  const char* name;  ///< e.g. "S1002 h28 e32.5 1:15 w140"
  const char* spec;  ///< the generator's input, e.g. "S1002:h=28,e=32.5,slope=1:15"
  rail::RadiusTableF32 f32;
  rail::RadiusTableQ q;
  float max_error_um;  ///< largest |table − definition| found by the generator (float table)
};

struct ContactPairTable {
  const char* name;  ///< the pair's spec, e.g. "wheel=S1002,rail=60E1,cant=1:40"
  rail::ContactTableF32 f32;
  rail::ContactTableQ q;
};

/// The profiles and pairs of this build, in the order of the CMake variables.
std::span<const ProfileTable> profiles() noexcept;
std::span<const ContactPairTable> contact_pairs() noexcept;

}  // namespace tread::lut
