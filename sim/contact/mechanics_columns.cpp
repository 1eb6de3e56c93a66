#include "contact/mechanics_columns.hpp"

#include <cmath>
#include <cstdio>

namespace tread::contact {
namespace {

constexpr const char* kWheels[2] = {"left", "right"};

void append(std::string& out, double v) {
  char buf[32];
  // Six significant digits; values that round to zero print as 0.
  std::snprintf(buf, sizeof buf, ",%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
  out += buf;
}

void append_wheel(std::string& out, const rail::WheelForces<double>& w) {
  for (int i = 0; i < 2; ++i) {
    const rail::PointForces<double>& p = w.point[i];
    append(out, p.normal_n);
    append(out, p.patch.a_mm);
    append(out, p.patch.b_mm);
    append(out, p.patch.p_max_mpa);
  }
  for (int i = 0; i < 2; ++i) {
    const rail::PointForces<double>& p = w.point[i];
    append(out, p.creepage.xi);
    append(out, p.creepage.eta);
    append(out, p.creepage.phi_per_mm);
    append(out, p.creep.fx_n);
    append(out, p.creep.fy_n);
    append(out, p.creep.mz_nmm);
  }
  append(out, w.yq.y_n);
  append(out, w.yq.q_n);
  append(out, w.derailment.y_over_q);
  append(out, w.derailment.limit);
  append(out, w.derailment.margin);
}

}  // namespace

std::string mechanics_header() {
  std::string h;
  for (const char* w : kWheels) {
    const std::string s = std::string("_") + w;
    for (const char* p : {"1", "2"}) {
      h += std::string(",n") + p + s + "_n,a" + p + s + "_mm,b" + p + s + "_mm,pmax" + p + s +
           "_mpa";
    }
    for (const char* p : {"1", "2"}) {
      h += std::string(",xi") + p + s + ",eta" + p + s + ",phi" + p + s + "_per_mm,fx" + p + s +
           "_n,fy" + p + s + "_n,mz" + p + s + "_nmm";
    }
    h += ",y" + s + "_n,q" + s + "_n,y_over_q" + s + ",nadal_limit" + s + ",nadal_margin" + s;
  }
  return h;
}

std::string mechanics_fields(const rail::WheelForces<double>& left,
                             const rail::WheelForces<double>& right) {
  std::string out;
  append_wheel(out, left);
  append_wheel(out, right);
  return out;
}

}  // namespace tread::contact
