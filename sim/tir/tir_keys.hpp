#pragma once
// The one table of .tir keys tread knows: each key's physical dimension (for [UNITS] conversion)
// and the tyre models whose property files carry it (for the missing-key warning).
//
// Dimensions. A value is converted to SI on read by multiplying with
//   length^l · force^f · angle^a · mass^m · time^t
// of the file's [UNITS] (e.g. a pressure is force/length², a stiffness force/length). Which keys
// are dimensional: the operating figures and limits (radii, widths, loads, pressures, stiffnesses,
// speeds, the slip- and inclination-angle limits ALPMIN/ALPMAX/CAMMIN/CAMMAX) and the inertia and
// damping figures of [INERTIA]/[VERTICAL]/[STRUCTURAL]. The Magic Formula coefficients (PCX1…,
// scale factors, Q_* ratios, PAC89/PAC94 A/B/C coefficients) are dimensionless: they are defined
// for SI inputs with angles in radians (PAC89/PAC94: kN and degrees by the formula itself) and no
// [UNITS] entry converts them; ANGLE converts only the four angle limits (and YAW_STIFFNESS, per
// radian). This follows the Adams tyre property-file convention that [UNITS] states the unit of
// the file's dimensional data, while the MF parameters are given for SI (TNO MF-Tyre manuals).
//
// Models. A key belongs to the property files of the models whose bit it carries; a key of no
// model (0) is optional everywhere (e.g. MF 5.2's Q_A1/Q_A2 contact-length terms, MFeval's
// fallback when 0) and never reported missing.
#include <cstdint>
#include <span>
#include <string_view>

namespace tread::tir {

/// Exponents of length, force, angle, mass and time.
struct Dimension {
  std::int8_t length = 0;
  std::int8_t force = 0;
  std::int8_t angle = 0;
  std::int8_t mass = 0;
  std::int8_t time = 0;

  constexpr bool is_none() const noexcept {
    return length == 0 && force == 0 && angle == 0 && mass == 0 && time == 0;
  }
  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
};

namespace dim {
inline constexpr Dimension kNone{};
inline constexpr Dimension kLength{1, 0, 0, 0, 0};
inline constexpr Dimension kForce{0, 1, 0, 0, 0};
inline constexpr Dimension kAngle{0, 0, 1, 0, 0};
inline constexpr Dimension kMass{0, 0, 0, 1, 0};
inline constexpr Dimension kTime{0, 0, 0, 0, 1};
inline constexpr Dimension kPressure{-2, 1, 0, 0, 0};
inline constexpr Dimension kStiffness{-1, 1, 0, 0, 0};         ///< force / length
inline constexpr Dimension kPerLength{-1, 0, 0, 0, 0};         ///< 1 / length
inline constexpr Dimension kTorsionStiffness{1, 1, -1, 0, 0};  ///< force·length / angle
inline constexpr Dimension kDamping{-1, 1, 0, 0, 1};           ///< force·time / length
inline constexpr Dimension kSpeed{1, 0, 0, 0, -1};
inline constexpr Dimension kAcceleration{1, 0, 0, 0, -2};
inline constexpr Dimension kFrequency{0, 0, 0, 0, -1};
inline constexpr Dimension kInertia{2, 0, 0, 1, 0};  ///< mass·length²
}  // namespace dim

/// Bits of the models a key belongs to.
using ModelSet = std::uint8_t;
namespace model {
inline constexpr ModelSet kOptional = 0;        ///< in no model: optional everywhere
inline constexpr ModelSet kMf52 = 1U << 0U;     ///< MF-Tyre 5.2 (FITTYP 6/21/52)
inline constexpr ModelSet kPac2002 = 1U << 1U;  ///< Adams PAC2002 (no FITTYP)
inline constexpr ModelSet kMf61 = 1U << 2U;
inline constexpr ModelSet kMf62 = 1U << 3U;
inline constexpr ModelSet kPac89 = 1U << 4U;
inline constexpr ModelSet kPac94 = 1U << 5U;
}  // namespace model

struct KeyInfo {
  std::string_view key;  ///< upper case, as TNO writes it (lookups are case-insensitive)
  Dimension dimension;
  ModelSet models;
};

/// Every key tread knows: all of TREAD_MF_PARAMETER_LIST (a test checks), the PAC89/PAC94
/// coefficients and the other numeric keys of TNO/Adams files.
std::span<const KeyInfo> key_table() noexcept;
/// The row of `key` (case-insensitive), or nullptr.
const KeyInfo* find_key_info(std::string_view key) noexcept;

}  // namespace tread::tir
