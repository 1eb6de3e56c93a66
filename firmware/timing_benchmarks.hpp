#pragma once
// Instruction counts on the target (under qemu's -icount: hal/cortex_m/systick_counter.hpp):
// a calibration loop of known length, the Magic Formula evaluation, the contact lookup and the
// encoding of output frames, each over fixed inputs, on the image's arithmetic (node_path.hpp:
// float or fixed point), printed as ticks to the semihosting console for
// scripts/target-timing.sh. Figures, not checks.

#include "cortex_m/systick_counter.hpp"

namespace tread::firmware {

void run_timing_benchmarks(hal::SysTickCounter& counter) noexcept;

}  // namespace tread::firmware
