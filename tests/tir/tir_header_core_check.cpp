// Compiled with the core's flags (-fno-exceptions -fno-rtti): the generated header must be usable
// in an ECU build. Also checks at compile time that lookups work in a constant expression.
#include "tir_header_core_check.hpp"

#include "generated/mf61_params_float.hpp"
#include "generated/mf61_tyre.hpp"

#include <iterator>

constexpr std::size_t kEntries = std::size(tyres::kMf61);
static_assert(tread::tir::find_index(tyres::kMf61, "vertical", "fnomin") < kEntries);
static_assert(tread::tir::find_index(tyres::kMf61, "", "FNOMIN") < kEntries);
static_assert(tread::tir::find_index(tyres::kMf61, "MODEL", "FNOMIN") == kEntries);
static_assert(tyres::kMf61[tread::tir::find_index(tyres::kMf61, "MODEL", "TYRESIDE")].text ==
              "RIGHT");
static_assert(!tyres::kMf61[tread::tir::find_index(tyres::kMf61, "MODEL", "TYRESIDE")].is_number);

double core_check_fnomin() noexcept {
  constexpr double fnomin = tread::tir::number_or(tyres::kMf61, "VERTICAL", "FNOMIN", -1.0);
  return fnomin;
}

// The MF parameter header too (what an ECU build includes).
static_assert(tyres::kMf61Float.fit_type == tread::mf::FitType::mf61);
