// The Magic Formula on four float lanes: packs four wheels' inputs, evaluates once, unpacks.
#include "mf/mf_evaluate_four.hpp"

#include "mf/mf_lanes.hpp"

namespace tread::mf {

namespace {

using lanes::F4;

/// Lane i of every float member of `out` (the members MfOutput lists, in order).
template <typename Fn>
void for_each_field(MfOutput<F4>& lanes_out, MfOutput<float>& out, Fn fn) {
  fn(lanes_out.fx_n, out.fx_n);
  fn(lanes_out.fy_n, out.fy_n);
  fn(lanes_out.fz_n, out.fz_n);
  fn(lanes_out.mx_nm, out.mx_nm);
  fn(lanes_out.my_nm, out.my_nm);
  fn(lanes_out.mz_nm, out.mz_nm);
  fn(lanes_out.kappa, out.kappa);
  fn(lanes_out.alpha_rad, out.alpha_rad);
  fn(lanes_out.gamma_rad, out.gamma_rad);
  fn(lanes_out.phit_1pm, out.phit_1pm);
  fn(lanes_out.vx_mps, out.vx_mps);
  fn(lanes_out.p_pa, out.p_pa);
  fn(lanes_out.re_m, out.re_m);
  fn(lanes_out.rho_m, out.rho_m);
  fn(lanes_out.contact_length_m, out.contact_length_m);
  fn(lanes_out.t_m, out.t_m);
  fn(lanes_out.mux, out.mux);
  fn(lanes_out.muy, out.muy);
  fn(lanes_out.omega_radps, out.omega_radps);
  fn(lanes_out.rl_m, out.rl_m);
  fn(lanes_out.contact_width_m, out.contact_width_m);
  fn(lanes_out.mzr_nm, out.mzr_nm);
  fn(lanes_out.cx_npm, out.cx_npm);
  fn(lanes_out.cy_npm, out.cy_npm);
  fn(lanes_out.cz_npm, out.cz_npm);
  fn(lanes_out.kya_nprad, out.kya_nprad);
  fn(lanes_out.sigmax_m, out.sigmax_m);
  fn(lanes_out.sigmay_m, out.sigmay_m);
  fn(lanes_out.kxk_n, out.kxk_n);
}

}  // namespace

__attribute__((flatten, target_clones("arch=x86-64-v3", "default"))) void evaluate_four(
    const MfParameters<float>& params, const std::array<MfInput<float>, 4>& inputs,
    const MfOptions& options, const std::array<MountedSide, 4>& sides,
    std::array<MfOutput<float>, 4>& outputs) noexcept {
  // Mirroring per wheel: y → −y on the way in and out of its lane.
  std::array<float, 4> y_sign{};
  MfInput<F4> in;
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const MfInput<float>& w = inputs[k];
    y_sign[k] = mirrored(sides[k], params.tyre_side) ? -1.0F : 1.0F;
    in.fz_n.v[i] = w.fz_n;
    in.kappa.v[i] = w.kappa;
    in.alpha_rad.v[i] = y_sign[k] * w.alpha_rad;
    in.gamma_rad.v[i] = y_sign[k] * w.gamma_rad;
    in.vx_mps.v[i] = w.vx_mps;
    in.phit_1pm.v[i] = y_sign[k] * w.phit_1pm;
    in.p_pa.v[i] = w.p_pa;
  }
  MfOptions lane_options = options;
  lane_options.side = MountedSide::as_measured;
  MfOutput<F4> out = evaluate(params, in, lane_options);
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    MfOutput<float>& o = outputs[k];
    for_each_field(out, o, [i](const F4& lane, float& value) { value = lane[i]; });
    o.status = out.status[i] ? Status::out_of_range : Status::ok;
    const float s = y_sign[k];
    o.fy_n *= s;
    o.mx_nm *= s;
    o.mz_nm *= s;
    o.mzr_nm *= s;
    o.alpha_rad *= s;
    o.gamma_rad *= s;
    o.phit_1pm *= s;
  }
}

}  // namespace tread::mf
