// Explicit instantiations for float and double: compiles the PAC89/PAC94 templates with the core's
// flags (no exceptions, no RTTI) on every toolchain, including the Cortex-M build.
#include "pac/pac89.hpp"
#include "pac/pac94.hpp"

namespace tread::pac {

template PacOutput<float> pac89_eval(const PacParams<float>&, const PacInput<float>&, Slip);
template PacOutput<double> pac89_eval(const PacParams<double>&, const PacInput<double>&, Slip);
template PacOutput<float> pac94_eval(const PacParams<float>&, const PacInput<float>&, Slip);
template PacOutput<double> pac94_eval(const PacParams<double>&, const PacInput<double>&, Slip);

}  // namespace tread::pac
