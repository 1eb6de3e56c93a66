// The spec strings of `tread contact`, `tread node --wheelset-profile` and `--wheel`: values are
// whole finite numbers or a clear error naming the option and the value (the fuzzer found
// "e=32.1e3085" answered by std::stod's own "stod", and "h=28mm" taken as 28).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/contact_setup.hpp"
#include "runtime/node_runtime.hpp"

namespace tread {
namespace {

std::string error_of(const std::string& spec) {
  try {
    static_cast<void>(contact::parse_wheel_spec(spec));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ContactSpec, WheelValuesAreWholeFiniteNumbers) {
  EXPECT_DOUBLE_EQ(contact::parse_wheel_spec("S1002:h=28,e=32.5").flange_height_mm, 28.0);
  EXPECT_EQ(error_of("EPS:h=30,e=32.1e3085"),
            "--wheel EPS:h=30,e=32.1e3085: e: '32.1e3085' is not a finite number");
  EXPECT_EQ(error_of("S1002:h=28mm"), "--wheel S1002:h=28mm: h: '28mm' is not a finite number");
  EXPECT_EQ(error_of("S1002:width=nan"),
            "--wheel S1002:width=nan: width: 'nan' is not a finite number");
  EXPECT_EQ(error_of("S1002:h="), "--wheel S1002:h=: h: '' is not a finite number");
  EXPECT_EQ(error_of("S1002:h=28,h=32"), "--wheel S1002:h=28,h=32: h given twice");
  EXPECT_EQ(error_of("S1002:chamfer=maybe"),
            "--wheel S1002:chamfer=maybe: chamfer: 'maybe' is none of 1, yes, true, 0, no, false");
}

TEST(ContactSpec, CantsAreOneInFiveOrFlatter) {
  EXPECT_DOUBLE_EQ(contact::parse_cant_rad("1:40"), std::atan(1.0 / 40.0));
  EXPECT_DOUBLE_EQ(contact::parse_cant_rad("1:5"), std::atan(0.2));
  EXPECT_DOUBLE_EQ(contact::parse_cant_rad("none"), 0.0);
  for (const char* bad : {"1:.40", "1:4", "1:0", "1:-40", "1:1e999", "1:40x", "2:40"}) {
    EXPECT_THROW(static_cast<void>(contact::parse_cant_rad(bad)), std::invalid_argument) << bad;
  }
}

TEST(ContactSpec, WheelsetProfileValuesAreWholeFiniteNumbers) {
  try {
    static_cast<void>(host::parse_wheelset_profile("wheel=S1002,rail=60E1,gauge=1435x"));
    FAIL() << "a gauge with a trailing word was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gauge=1435x"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
  }
}

// Dimensions no wheelset has are refused before any table is built (a negative r0 gave a contact
// table, the LUT generator wrote r0 = 1e12 mm, a b2b wider than the gauge was taken).
TEST(ContactSpec, WheelsetDimensionsAreAWheelsets) {
  const auto error = [](const std::string& spec) {
    try {
      contact::check_wheelset_dimensions(contact::parse_wheelset_profile(spec));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error("wheel=S1002,rail=60E1"), "accepted");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,r0=460,r0=900"), "--wheelset-profile: 'r0' given twice");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,gauge=1000,b2b=925"), "accepted");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,r0=-5"),
            "--r0 -5: a wheel's rolling radius in mm lies within 100 … 1500 mm");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,r0=0.46"),
            "--r0 0.46: a wheel's rolling radius in mm lies within 100 … 1500 mm");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,r0-right=1e12"),
            "--r0-right 1e+12: a wheel's rolling radius in mm lies within 100 … 1500 mm");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,gauge=0"), "--gauge 0, --b2b 1360: both must be > 0 (mm)");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,gauge=1e300,b2b=1e299"),
            "--gauge 1e+300: a track gauge in mm lies within 300 … 2000 mm");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,gauge=1.435"),
            "--gauge 1.435: a track gauge in mm lies within 300 … 2000 mm");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,gauge=600,b2b=530"), "accepted");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,b2b=1500"),
            "--b2b 1500 mm is not below --gauge 1435 mm: the wheels' backs would stand outside the "
            "rails");
  // A built-in wheel's flanges must leave play: 1375 + 2 · 28.5 = 1432 < 1435, 1380 + 65 is not.
  EXPECT_EQ(error("wheel=S1002:e=28.5,rail=60E1,b2b=1375"), "accepted");
  EXPECT_EQ(error("wheel=S1002,rail=60E1,b2b=1380"),
            "--b2b 1380 mm with two flanges of e = 32.5 mm (1445 mm) does not fit in --gauge 1435 "
            "mm: the wheelset has no lateral play");
}

}  // namespace
}  // namespace tread
