#pragma once
// Inputs and outputs of one Magic Formula evaluation (one wheel, one instant). ISO-W axes, SI
// units, as MFeval.

#include "core/status.hpp"

namespace tread::mf {

template <typename T>
struct MfInput {
  T fz_n = T(0);       ///< vertical load (negative → 0)
  T kappa = T(0);      ///< longitudinal slip (−1 = locked wheel)
  T alpha_rad = T(0);  ///< side slip angle
  T gamma_rad = T(0);  ///< inclination angle
  T vx_mps = T(0);     ///< forward speed of the wheel centre
  T phit_1pm = T(0);   ///< turn slip (used only with MfOptions::use_turn_slip)
  T p_pa = T(0);       ///< inflation pressure; 0 (or less, or NaN) → the file's INFLPRES
};

/// The type of MfOutput<T>::status: a Status for the scalars; the four-lane scalar of
/// mf_lanes.hpp holds per-lane masks instead (lanes::LaneStatus).
template <typename T>
struct StatusFor {
  using type = Status;
};

/// Everything MFeval's mfeval() returns except its row-to-row finite difference (iKya). The
/// processed inputs (kappa, alpha_rad, ...) are what MFeval writes back: after the low-speed
/// reduction and the limits, like MFeval's output columns 7…12.
template <typename T>
struct MfOutput {
  T fx_n = T(0), fy_n = T(0), fz_n = T(0);
  T mx_nm = T(0), my_nm = T(0), mz_nm = T(0);
  T kappa = T(0), alpha_rad = T(0), gamma_rad = T(0), phit_1pm = T(0), vx_mps = T(0), p_pa = T(0);
  T re_m = T(0);                                  ///< effective rolling radius
  T rho_m = T(0);                                 ///< vertical deflection
  T contact_length_m = T(0);                      ///< 2a
  T t_m = T(0);                                   ///< pneumatic trail
  T mux = T(0), muy = T(0);                       ///< friction coefficients
  T omega_radps = T(0);                           ///< wheel speed (from Vx, κ and Re)
  T rl_m = T(0);                                  ///< loaded radius
  T contact_width_m = T(0);                       ///< 2b
  T mzr_nm = T(0);                                ///< residual aligning moment
  T cx_npm = T(0), cy_npm = T(0), cz_npm = T(0);  ///< carcass / vertical stiffnesses
  T kya_nprad = T(0);                             ///< cornering stiffness
  T sigmax_m = T(0), sigmay_m = T(0);             ///< relaxation lengths
  T kxk_n = T(0);                                 ///< longitudinal slip stiffness
  /// @retval Status::ok           every output is finite and no input left the envelope
  /// @retval Status::out_of_range an input lay outside the finite-arithmetic envelope (see
  ///                              mf_evaluate.hpp) and was clamped to it. The limits of useMode
  ///                              1xx do not set it (MFeval only warns).
  /// @retval Status::non_finite   an output came out NaN or infinite (a NaN input, or parameters
  ///                              no tyre has: VERTICAL_STIFFNESS, FNOMIN or UNLOADED_RADIUS 0,
  ///                              ...); every such output is 0, the finite ones are kept. Takes
  ///                              precedence over out_of_range.
  typename StatusFor<T>::type status{};
};

}  // namespace tread::mf
