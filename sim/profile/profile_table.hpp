#pragma once
// The seed's ASCII table of a wheel profile (its appendix "Vzor ASCII tabulky", with the column
// names put right): a title, the flange, then `y [mm]  z [mm]  tan` rows from the field side
// (y descending) to the wheel back, z and tan with 5 decimals (tan = inf at the vertical back).

#include <iosfwd>
#include <vector>

#include "profile/wheel_profile.hpp"

namespace tread::profile {

/// y from y_max down to y_min at `step_mm` (both ends included), snapped to the step's decimals.
std::vector<double> descending_grid(const WheelProfile& wheel, double step_mm);

/// Digits after the point needed to print multiples of `step_mm` exactly (1 … 6).
int step_decimals(double step_mm);

void write_profile_table(std::ostream& out, const WheelProfile& wheel, double step_mm);

}  // namespace tread::profile
