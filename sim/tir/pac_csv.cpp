#include "tir/pac_csv.hpp"

#include <array>
#include <istream>
#include <ostream>
#include <vector>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "tir/tir_file.hpp"

namespace tread::tir {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  for (const char c : line) {
    if (c == ',') {
      cells.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  cells.push_back(cur);
  for (auto& s : cells) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    s = b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  }
  return cells;
}

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
  auto r =
      o.model == PacModel::kPac89 ? pac::pac89_eval(p, in, o.slip) : pac::pac94_eval(p, in, o.slip);
  if (o.iso_w) r = pac::to_iso_w(r);
  return {static_cast<double>(r.fx_n),  static_cast<double>(r.fy_n),  static_cast<double>(r.mz_nm),
          static_cast<double>(r.mx_nm), static_cast<double>(r.my_nm), r.status};
}

}  // namespace

std::size_t evaluate_pac_csv(const pac::PacParams<double>& params, const PacCsvOptions& options,
                             std::istream& in, const std::string& in_name, std::ostream& out) {
  const std::array<const char*, 4> names = {"Fz_N", "kappa", "alpha_rad", "gamma_rad"};
  std::array<std::size_t, 4> col{};
  std::size_t width = 0;
  bool have_header = false;
  const auto pf = convert<float>(params);
  std::string line;
  int line_no = 0;
  std::size_t rows = 0;
  out.precision(17);
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line.front() == '#') continue;
    const auto cells = split(line);
    if (!have_header) {
      for (std::size_t k = 0; k < names.size(); ++k) {
        std::size_t found = cells.size();
        for (std::size_t j = 0; j < cells.size(); ++j) {
          if (cells[j] != names[k]) continue;
          if (found != cells.size()) {
            throw TirError(in_name, line_no, std::string("repeated column ") + names[k]);
          }
          found = j;
        }
        if (found == cells.size()) {
          throw TirError(in_name, line_no, std::string("missing column ") + names[k]);
        }
        col[k] = found;
      }
      width = cells.size();
      have_header = true;
      out << "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,Fx_N,Fy_N,Mz_Nm,Mx_Nm,My_Nm,status\n";
      continue;
    }
    if (cells.size() != width) {
      throw TirError(
          in_name, line_no,
          "expected " + std::to_string(width) + " cells, got " + std::to_string(cells.size()));
    }
    std::array<double, 4> v{};
    for (std::size_t k = 0; k < names.size(); ++k) {
      const auto n = parse_number(cells[col[k]]);
      if (!n) {
        throw TirError(in_name, line_no,
                       std::string(names[k]) + " is not a finite number: '" + cells[col[k]] + "'");
      }
      v[k] = *n;
    }
    const auto r = options.use_float ? eval_as(pf, options, v) : eval_as(params, options, v);
    out << v[0] << ',' << v[1] << ',' << v[2] << ',' << v[3] << ',' << r.fx_n << ',' << r.fy_n
        << ',' << r.mz_nm << ',' << r.mx_nm << ',' << r.my_nm << ',' << to_string(r.status) << '\n';
    ++rows;
  }
  if (!have_header) throw TirError(in_name, line_no, "no header row");
  return rows;
}

}  // namespace tread::tir
