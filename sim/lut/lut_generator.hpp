#pragma once
// Builds the lookup tables of lut/ from the exact double definitions and writes them as C++ source.

#include <string>
#include <vector>

#include "contact/rigid_contact.hpp"

namespace tread::host {

struct RadiusTableData {
  std::string name;
  std::string spec;
  double y_first_mm{0.0};
  double step_mm{0.0};
  std::vector<double> z_mm;
  double max_error_um{
      0.0};  ///< of the float table against the definition, checked at 20 points per step
};

/// z(y) of a built-in wheel ("S1002:h=28,e=32.5,slope=1:40") on the running surface (from 5 mm
/// beyond the flange tip to the start of the chamfer / outer face) with the largest step (µm
/// multiple) whose linear interpolation stays within `max_error_um` of the definition.
/// Throws std::runtime_error if even the finest step cannot meet it.
RadiusTableData make_radius_table(const std::string& wheel_spec, double max_error_um = 1.0);

struct ContactTableData {
  std::string spec;
  contact::ContactTable table;
};

/// The contact table of a wheel/rail pair (spec as tread node's --wheelset-profile) over
/// y ∈ [−ymax, ymax] at `step_mm`.
ContactTableData make_contact_table(const std::string& pair_spec, double ymax_mm = 12.0,
                                    double step_mm = 0.1);

/// The C++ source of lut/tread_lut.hpp's tables. Deterministic: the same inputs give the same
/// bytes.
std::string write_lut_source(const std::vector<RadiusTableData>& profiles,
                             const std::vector<ContactTableData>& pairs);

}  // namespace tread::host
