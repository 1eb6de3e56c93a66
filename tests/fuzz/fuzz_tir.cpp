// .tir property files (tir/tir_file.hpp, mf/mf_parameters_from_tir.hpp) from bytes no one wrote:
// - parse_tir either returns or throws an error naming the file;
// - what it parsed, written and parsed again, writes the same text (the writer's output is a file
//   the reader takes back unchanged), and every entry reads as a number or fails naming the file;
// - a file the Magic Formula accepts gives, at a few operating points, outputs that are all finite
//   in double, float and fixed point (an output the arithmetic cannot give is 0 with status
//   non_finite, never NaN or infinity), whatever its coefficients.
#include <array>
#include <string>

#include "fixed/fixed64.hpp"
#include "fuzz_support.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "mf/mf_options.hpp"
#include "tir/tir_file.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;

constexpr const char* kSource = "fuzz.tir";

bool output_ok(double v) {
  return fuzz::is_finite(v);
}
bool output_ok(float v) {
  return fuzz::is_finite(static_cast<double>(v));
}
bool output_ok(fixed::Fixed64 v) {
  return v.valid();
}

template <typename T>
void check_outputs(const mf::MfOutput<T>& o, const char* path) {
  const std::array values{o.fx_n,
                          o.fy_n,
                          o.fz_n,
                          o.mx_nm,
                          o.my_nm,
                          o.mz_nm,
                          o.re_m,
                          o.rho_m,
                          o.rl_m,
                          o.t_m,
                          o.mux,
                          o.muy,
                          o.cz_npm,
                          o.kya_nprad,
                          o.kxk_n,
                          o.mzr_nm,
                          o.contact_length_m,
                          o.sigmax_m,
                          o.sigmay_m};
  for (std::size_t i = 0; i < values.size(); ++i) {
    fuzz_check(output_ok(values[i]), std::string(path) + ": output " + std::to_string(i) +
                                         " not finite (the core promises 0 and non_finite)");
  }
}

template <typename T, typename P>
void evaluate_at(const mf::MfParameters<P>& p, const mf::MfOptions& options, T fz, T kappa, T alpha,
                 T gamma, T vx, const char* path) {
  mf::MfInput<T> in;
  in.fz_n = fz;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.gamma_rad = gamma;
  in.vx_mps = vx;
  check_outputs(mf::evaluate(p, in, options), path);
}

void evaluate_everywhere(const mf::MfParameters<double>& p) {
  mf::MfOptions options = mf::options_from_use_mode(111).value;
  options.extras = true;
  const mf::MfParameters<float> pf = mf::convert_parameters<float>(p);
  const mf::MfParameters<fixed::Fixed64> pq = mf::to_fixed_parameters(p);
  constexpr std::array<double, 3> kLoadsN{0.0, 4000.0, 12000.0};
  for (const double fz : kLoadsN) {
    evaluate_at<double>(p, options, fz, -0.1, 0.05, 0.02, 16.7, "double");
    evaluate_at<float>(pf, options, static_cast<float>(fz), 0.3F, -0.2F, 0.0F, 1.0F, "float");
    evaluate_at<fixed::Fixed64>(pq, options, fixed::Fixed64::from_double(fz), fixed::Fixed64(0.05),
                                fixed::Fixed64(0.1), fixed::Fixed64(-0.03), fixed::Fixed64(25.0),
                                "fixed");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tir::TirFile file;
  if (!fuzz::returns_or_names_source(kSource, [&] { file = tir::parse_tir(text, kSource); })) {
    return 0;
  }
  for (const std::string& w : file.warnings()) fuzz::check_message(kSource, w);
  const std::string written = tir::write_tir(file);
  tir::TirFile again;
  if (!fuzz::returns_or_names_source(kSource, [&] { again = tir::parse_tir(written, kSource); })) {
    fuzz::fuzz_fail("the writer's output does not parse again");
  }
  fuzz_check(tir::write_tir(again) == written, "write(parse(write(f))) != write(f)");
  for (const tir::Section& s : file.sections()) {
    for (const tir::Entry* e : s.entries()) {
      static_cast<void>(fuzz::returns_or_names_source(
          kSource, [&] { static_cast<void>(file.number(s.name, e->key)); }));
    }
  }
  tyre::MfTirParameters params;
  if (fuzz::returns_or_names_source(kSource,
                                    [&] { params = tyre::mf_parameters_from_tir(file); })) {
    fuzz::check_message(kSource, params.warning);
    evaluate_everywhere(params.params);
  }
  return 0;
}
