#include "fit/mf_coefficients.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace tread::fit {
namespace {

struct Row {
  const char* section;
  const char* key;
  double value;
};

constexpr std::array<Row, mf::kMfParameterCount> kRows = {{
#define TREAD_FIT_ROW(member, section, key, value, description) {section, key, value},
    TREAD_MF_PARAMETER_LIST(TREAD_FIT_ROW)
#undef TREAD_FIT_ROW
}};

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

int coefficient_index(std::string_view key) {
  for (std::size_t i = 0; i < kRows.size(); ++i) {
    if (key == kRows[i].key) return static_cast<int>(i);
  }
  return -1;
}

int required_coefficient_index(std::string_view key) {
  const int i = coefficient_index(key);
  if (i < 0) throw std::invalid_argument("unknown Magic Formula coefficient " + std::string(key));
  return i;
}

const char* coefficient_key(int index) {
  return kRows[static_cast<std::size_t>(index)].key;
}
const char* coefficient_section(int index) {
  return kRows[static_cast<std::size_t>(index)].section;
}
double coefficient_default(int index) {
  return kRows[static_cast<std::size_t>(index)].value;
}

CoefficientBounds coefficient_bounds(std::string_view key) {
  if (key == "PCX1" || key == "PCY1") return {1.0 + 1e-6, 3.0};
  if (key == "PEX1" || key == "PEY1" || key == "QEZ1" || key == "REX1" || key == "REY1") {
    return {-kInf, 1.0};
  }
  if (key == "QCZ1" || key == "RCX1" || key == "RCY1") return {0.05, 3.0};
  if (key == "PKY4") return {0.1, 3.0};
  if (key == "RBX1" || key == "RBY1" || key == "QBZ1") return {0.0, kInf};
  // Br = QBZ9 + QBZ10·By·Cy: unbounded, a noisy Mz can pull Mzr into a spike of width ~1e-3 rad at
  // αr = 0 (seen: QBZ9 → −1900 from 226). |Br·α| ≲ 2 at α = 0.01 still fits every file here.
  if (key == "QBZ9") return {-400.0, 400.0};
  if (key == "QBZ10") return {-100.0, 100.0};
  return {-kInf, kInf};
}

}  // namespace tread::fit
