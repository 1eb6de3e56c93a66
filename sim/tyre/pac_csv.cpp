#include "tyre/pac_csv.hpp"

#include <array>
#include <cmath>
#include <istream>
#include <ostream>
#include <vector>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "tir/tir_file.hpp"

namespace tread::tyre {

namespace {

template <typename T>
pac::PacParams<T> convert(const pac::PacParams<double>& p) {
  pac::PacParams<T> q;
  for (std::size_t i = 0; i < p.a.size(); ++i) q.a[i] = static_cast<T>(p.a[i]);
  for (std::size_t i = 0; i < p.b.size(); ++i) q.b[i] = static_cast<T>(p.b[i]);
  for (std::size_t i = 0; i < p.c.size(); ++i) q.c[i] = static_cast<T>(p.c[i]);
  q.unloaded_radius_m = static_cast<T>(p.unloaded_radius_m);
  q.rolling_resistance = static_cast<T>(p.rolling_resistance);
  q.lateral_stiffness_npm = static_cast<T>(p.lateral_stiffness_npm);
  q.fz_max_n = static_cast<T>(p.fz_max_n);
  q.kappa_max = static_cast<T>(p.kappa_max);
  q.alpha_max_rad = static_cast<T>(p.alpha_max_rad);
  q.gamma_max_rad = static_cast<T>(p.gamma_max_rad);
  return q;
}

template <typename T>
pac::PacOutput<double> eval_as(const pac::PacParams<T>& p, const PacCsvOptions& o,
                               const std::array<double, 4>& v) {
  const pac::PacInput<T> in{static_cast<T>(v[0]), static_cast<T>(v[1]), static_cast<T>(v[2]),
                            static_cast<T>(v[3])};
  auto r = o.model == tir::PacModel::kPac89 ? pac::pac89_eval(p, in, o.slip)
                                            : pac::pac94_eval(p, in, o.slip);
  if (o.iso_w) r = pac::to_iso_w(r);
  return {static_cast<double>(r.fx_n),  static_cast<double>(r.fy_n),  static_cast<double>(r.mz_nm),
          static_cast<double>(r.mx_nm), static_cast<double>(r.my_nm), r.status};
}

}  // namespace

std::size_t evaluate_pac_csv(const pac::PacParams<double>& params, const PacCsvOptions& options,
                             std::istream& in, const std::string& in_name, std::ostream& out,
                             PacCsvTally* tally) {
  using Q = InputQuantity;
  InputTable table(in, in_name, options.table);
  if (tally != nullptr) {
    for (const Q q : {Q::vx, Q::phit, Q::pressure}) {
      if (table.has(q)) tally->unused_columns.push_back(table.column_name(q));
    }
  }
  const auto pf = convert<float>(params);
  std::size_t rows = 0;
  out.precision(17);
  out << "# tread pac eval: "
      << (options.iso_w ? "ISO-W (TYDEX W) axes" : "the PAC89/PAC94 model's own axes")
      << ", SI units (inputs read in " << to_string(options.table.convention)
      << " axes and converted to ISO-W)\n";
  out << "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,Fx_N,Fy_N,Mz_Nm,Mx_Nm,My_Nm,status\n";
  while (const auto row = table.next()) {
    const std::array<double, 4> v = {(*row)[Q::fz], (*row)[Q::kappa], (*row)[Q::alpha],
                                     (*row)[Q::gamma]};
    const auto r = options.use_float ? eval_as(pf, options, v) : eval_as(params, options, v);
    const bool finite = std::isfinite(r.fx_n) && std::isfinite(r.fy_n) && std::isfinite(r.mz_nm) &&
                        std::isfinite(r.mx_nm) && std::isfinite(r.my_nm);
    if (!finite && r.status == Status::ok) {
      // Never a NaN or Inf under status ok. The core already writes a non-finite output as 0
      // with Status::non_finite; this is the last check where numbers leave the program.
      throw tir::TirError(in_name, row->line,
                          "the coefficients give a non-finite output under status ok for this row");
    }
    out << v[0] << ',' << v[1] << ',' << v[2] << ',' << v[3] << ',' << r.fx_n << ',' << r.fy_n
        << ',' << r.mz_nm << ',' << r.mx_nm << ',' << r.my_nm << ',' << to_string(r.status) << '\n';
    ++rows;
    if (tally != nullptr && r.status != Status::ok) {
      const bool range = r.status == Status::out_of_range;
      std::size_t& count = range ? tally->out_of_range : tally->other;
      int& first = range ? tally->first_out_of_range_line : tally->first_other_line;
      if (count++ == 0) first = row->line;
    }
  }
  return rows;
}

}  // namespace tread::tyre
