// The libgpiod backend's error paths. This kernel has neither gpio-sim nor gpio-mockup, so the
// happy path is checked on real hardware (README: "Checking the GPIO backend on hardware").
#include "gpiod/gpiod_pin.hpp"

#include <gtest/gtest.h>

#include "hal_concepts.hpp"

namespace tread::hal {
namespace {

static_assert(OutputPin<GpiodPin>);

TEST(GpiodPin, MissingChipIsAClearErrorAndThePinStaysInert) {
  GpiodPin pin;
  EXPECT_EQ(pin.open("gpiochip97", 3), Status::invalid_argument);
  EXPECT_FALSE(pin.is_open());
  EXPECT_NE(pin.error().find("gpiochip97: no such GPIO chip"), std::string::npos) << pin.error();
  EXPECT_EQ(pin.set(true), Status::unsupported);  // the loop runs on without the pin
}

TEST(GpiodPin, ANonexistentDevicePathIsAClearError) {
  GpiodPin pin;
  EXPECT_EQ(pin.open("/dev/gpiochip-none", 0), Status::invalid_argument);
  EXPECT_NE(pin.error().find("/dev/gpiochip-none"), std::string::npos);
}

}  // namespace
}  // namespace tread::hal
