#pragma once
// The Cortex-M SysTick timer as a free-running tick counter for measuring code on the target: a
// 24-bit down-counter on the processor clock, widened here to 32 bits by counting wraps (call
// ticks() at least once per 2^24 ticks). Under qemu-system-arm with `-icount shift=0` every
// instruction advances the emulated clock by 1 ns, so ticks count instructions: on the MPS2 boards
// (25 MHz) one tick is 40 instructions.

#include <cstdint>

namespace tread::hal {

class SysTickCounter {
 public:
  /// Starts SysTick from its full 24-bit reload value, processor clock, no interrupt.
  void start() noexcept {
    reg(kRvr) = kMask;
    reg(kCvr) = 0U;  // any write clears the counter (and COUNTFLAG)
    reg(kCsr) = kEnable | kClkSource;
    last_ = kMask;
    wraps_ = 0;
  }

  /// Ticks since start() (modulo 2^32).
  std::uint32_t ticks() noexcept {
    const std::uint32_t now = reg(kCvr) & kMask;
    if (now > last_) {
      ++wraps_;  // counted down through zero and reloaded
    }
    last_ = now;
    return (wraps_ << 24U) + (kMask - now);
  }

 private:
  static constexpr std::uintptr_t kCsr = 0xE000E010U;
  static constexpr std::uintptr_t kRvr = 0xE000E014U;
  static constexpr std::uintptr_t kCvr = 0xE000E018U;
  static constexpr std::uint32_t kEnable = 1U << 0U;
  static constexpr std::uint32_t kClkSource = 1U << 2U;
  static constexpr std::uint32_t kMask = 0x00FFFFFFU;

  static volatile std::uint32_t& reg(std::uintptr_t address) noexcept {
    return *reinterpret_cast<volatile std::uint32_t*>(address);
  }

  std::uint32_t last_{kMask};
  std::uint32_t wraps_{0};
};

}  // namespace tread::hal
