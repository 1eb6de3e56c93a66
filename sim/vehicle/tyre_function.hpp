#pragma once
// The tyre as the vehicle model's driver sees it: a function from one wheel's kinematics to its
// forces. Over CAN it is the node's answer; in process it is the Magic Formula in double.

#include <cstddef>
#include <functional>

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "vehicle/vehicle_model.hpp"

namespace tread::vehicle {

using TyreFunction = std::function<WheelForces(std::size_t wheel, const WheelKinematics&)>;

/// tread::mf::evaluate<double> on a copy of `params`, the same for every wheel (as the node does:
/// one .tir, options.side for all wheels). `options.extras` is switched off (forces only).
TyreFunction mf_tyre_function(const mf::MfParameters<double>& params, mf::MfOptions options = {});

/// The slip κ ∈ [−1, 0] of the largest braking force |Fx| of the tyre at load fz_n (α = γ = 0),
/// by a scan at 0.001 and a golden-section refinement. `wheel` is passed to the tyre function.
double peak_braking_slip(const TyreFunction& tyre, std::size_t wheel, double fz_n, double vx_mps);

}  // namespace tread::vehicle
