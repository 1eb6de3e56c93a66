// Klingel wavelength: the closed form, its inverse, and agreement with the wavelength that the
// EN 15302 Annex B integration finds for a linear delta r.
#include "contact/klingel.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "contact/equivalent_conicity.hpp"

namespace tread::contact {
namespace {

TEST(Klingel, WavelengthOfAStandardWheelset) {
  // 2 pi sqrt(750 * 460 / 0.15) = 2 pi * 1516.575...
  EXPECT_NEAR(klingel_wavelength_mm(0.15, 460.0), 2.0 * 3.14159265358979 * 1516.5750888103, 1e-6);
  EXPECT_NEAR(klingel_conicity(klingel_wavelength_mm(0.23, 445.0, 745.0), 445.0, 745.0), 0.23,
              1e-12);
  EXPECT_TRUE(std::isnan(klingel_wavelength_mm(0.0, 460.0)));
  EXPECT_TRUE(std::isnan(klingel_conicity(-1.0, 460.0)));
}

TEST(Klingel, MatchesTheIntegratedKinematicEquation) {
  ContactTable t;
  t.y_first_mm = -10.0;
  t.y_step_mm = 0.1;
  for (int i = 0; i <= 200; ++i) {
    const double y = -10.0 + 0.1 * i;
    t.y_mm.push_back(y);
    t.delta_r_mm.push_back(2.0 * 0.2 * y);
  }
  const ConicityResult r = equivalent_conicity(t, 3.0);
  EXPECT_NEAR(r.wavelength_mm, klingel_wavelength_mm(0.2, 460.0), 1e-4 * r.wavelength_mm);
}

}  // namespace
}  // namespace tread::contact
