// Run-time conversions between Fixed64 and double: host code and tests only (they use floating
// point; a firmware image that never calls them does not link them).
#include "fixed/fixed64.hpp"

namespace tread::fixed {

Fixed64 Fixed64::from_double(double value) {
  const double scaled = value * 4294967296.0;
  if (!(scaled < 9.2233720368547748e18) || !(scaled > -9.2233720368547748e18)) {
    return invalid();  // NaN, ±inf or outside the range
  }
  return from_raw(static_cast<std::int64_t>(scaled < 0.0 ? scaled - 0.5 : scaled + 0.5));
}

double Fixed64::to_double() const {
  if (!valid()) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(raw_) / 4294967296.0;
}

}  // namespace tread::fixed
