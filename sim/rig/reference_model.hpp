#pragma once
// The rig's reference: the tyre model in double on the inputs a node received (after quantisation),
// to compare the node's float answers with.

#include "mf/mf_evaluate.hpp"
#include "proto/data_model.hpp"

namespace tread::host {

inline mf::MfOutput<double> reference_output(const mf::MfParameters<double>& params,
                                             const proto::WheelInput& wheel,
                                             const mf::MfOptions& options) {
  mf::MfInput<double> in;
  in.fz_n = static_cast<double>(wheel.fz_n);
  in.kappa = static_cast<double>(wheel.kappa);
  in.alpha_rad = static_cast<double>(wheel.alpha_rad);
  in.gamma_rad = static_cast<double>(wheel.gamma_rad);
  in.vx_mps = static_cast<double>(wheel.vx_mps);
  return mf::evaluate(params, in, options);
}

}  // namespace tread::host
