#pragma once
// The contact-mechanics columns `tread contact --load` appends to the geometry table: per wheel,
// the normal force, Hertz ellipse and maximum pressure of each contact point (1: main, 2: second
// point of a two-point contact, zero when unloaded), the creepages and creep forces at each point
// (in the point's contact frame, lateral toward the wheel's field side), the wheel's Y (toward the
// track centre) and Q, Y/Q, Nadal's limit and the margin to it.

#include <string>
#include <vector>

#include "contact/contact_mechanics.hpp"

namespace tread::contact {

/// Column names, comma-separated, starting with a comma.
std::string mechanics_header();

/// One row's fields, comma-separated, starting with a comma (same order as the header).
std::string mechanics_fields(const rail::WheelForces<double>& left,
                             const rail::WheelForces<double>& right);

}  // namespace tread::contact
