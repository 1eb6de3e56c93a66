#pragma once
// Coefficients of the Adams Tire PAC89 / PAC94 Magic Formula models (plain data).
//
// The coefficients work in the models' own units: Fz in kN, slip angle α and inclination γ in
// degrees, longitudinal slip κ in percent; forces in N, moments in N·m. PAC89 uses a0…a13, b0…b10,
// c0…c17; PAC94 adds a14…a17, b11…b13, c18…c20 (unused entries are ignored by PAC89 and should be 0
// for a PAC89 set). Loaders (.tir, Chrono JSON) live host-side in sim/tir/pac_coefficients.hpp.

#include <array>

#include "core/status.hpp"

namespace tread::pac {

template <typename T>
struct PacParams {
  std::array<T, 18> a{};  ///< lateral force Fy: a0 … a17
  std::array<T, 14> b{};  ///< longitudinal force Fx: b0 … b13
  std::array<T, 21> c{};  ///< aligning moment Mz: c0 … c20

  T unloaded_radius_m{0};      ///< R in My = f·Fz·R (seed eq. 52); 0 → My = 0
  T rolling_resistance{0};     ///< f in My = f·Fz·R
  T lateral_stiffness_npm{0};  ///< C_Fα in Mx = −Fz·Fy/C_Fα (seed eq. 50–51); 0 → Mx = 0

  // Input limits applied before evaluation (the models are fits, meaningless far outside their
  // data; the limits also keep every intermediate finite for any finite input).
  T fz_max_n{100000};  ///< Fz is clamped to [0, fz_max_n]; Fz ≤ 0 gives zero forces
  T kappa_max{1};      ///< |κ| ≤ kappa_max (1 = 100 %)
  T alpha_max_rad = T(1.5620696805349385);  ///< |α| ≤ 89.5° (tan α stays finite in combined slip)
  T gamma_max_rad{0.5};                     ///< |γ| ≤ gamma_max_rad
};

/// Evaluation mode: pure slip (each force from its own slip only) or combined slip.
enum class Slip : unsigned char { kPure, kCombined };

/// SI inputs. κ is the practical longitudinal slip (−1 = locked wheel), α and γ in radians.
template <typename T>
struct PacInput {
  T fz_n{0};
  T kappa{0};
  T alpha_rad{0};
  T gamma_rad{0};
};

/// SI outputs, in the axis system of the coefficient set (Adams PAC89: "modified SAE"; see
/// to_iso_w()).
template <typename T>
struct PacOutput {
  T fx_n{0};
  T fy_n{0};
  T mz_nm{0};
  T mx_nm{0};
  T my_nm{0};
  /// @retval Status::ok               every input within the limits, every output finite
  /// @retval Status::out_of_range     an input lay outside the limits and was clamped (outputs
  ///                                  valid for the clamped input; Fz < 0 counts, Fz = 0 does not)
  /// @retval Status::invalid_argument an input was NaN or infinite (all outputs 0)
  /// @retval Status::non_finite       an output came out NaN or infinite (coefficients no tyre
  ///                                  has); each such output is 0. Takes precedence over
  ///                                  out_of_range.
  Status status{Status::ok};
};

/// Converts outputs from the PAC89 model axes to ISO-W (as Chrono's ChPac89Tire does: Fx and Mx
/// unchanged, Fy, My and Mz change sign; α and γ are used unchanged).
template <typename T>
constexpr PacOutput<T> to_iso_w(const PacOutput<T>& o) noexcept {
  return {o.fx_n, -o.fy_n, -o.mz_nm, o.mx_nm, -o.my_nm, o.status};
}

}  // namespace tread::pac
