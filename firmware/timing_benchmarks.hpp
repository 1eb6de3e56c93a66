#pragma once
// Instruction counts on the target (under qemu's -icount: hal/cortex_m/systick_counter.hpp):
// a calibration loop of known length, the Magic Formula evaluation, the contact lookup and the
// encoding of output frames, each over fixed inputs, printed as ticks to the semihosting console
// for scripts/target-timing.sh. Figures, not checks.

#include "cortex_m/systick_counter.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "rail/contact_lookup.hpp"

namespace tread::firmware {

void run_timing_benchmarks(hal::SysTickCounter& counter, const mf::MfParameters<float>& tyre,
                           const mf::MfOptions& options,
                           const rail::ContactTableF32& table) noexcept;

}  // namespace tread::firmware
