#pragma once
// PNG plots of a contact table through gnuplot (gnuplot-nox): delta r(y), and the contact positions
// on the left and right wheel. The C++ sciplot library is not packaged in Debian bookworm (the
// `libsciplot-dev` package is an unrelated Xt widget), so the data go to gnuplot directly.

#include <string>

#include "contact/rigid_contact.hpp"

namespace tread::contact {

/// Writes `png_path` (two panels). Throws std::runtime_error when gnuplot fails or is missing.
void plot_contact_table(const ContactTable& table, const std::string& title,
                        const std::string& png_path);

}  // namespace tread::contact
