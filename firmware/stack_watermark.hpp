#pragma once
// The stack's high-water mark: paint() fills the free stack below the caller's frame with a
// pattern, peak_bytes() finds how far down the pattern was overwritten since. The stack runs from
// _estack (top of RAM) down towards _ebss (sections.ld). For the RAM figure of
// scripts/target-timing.sh.

#include <cstddef>
#include <cstdint>

extern "C" {
extern std::uint32_t _ebss[];
extern std::uint32_t _estack[];
}

namespace tread::firmware {

class StackWatermark {
 public:
  /// Call early (from main): paints from the end of .bss up to 256 bytes below the caller's frame.
  static void paint() noexcept {
    std::uint32_t* sp = nullptr;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (volatile std::uint32_t* p = _ebss; p < sp - 64; ++p) {
      *p = kPattern;
    }
  }

  /// Bytes of stack used at most since paint() (from the top of RAM).
  static std::size_t peak_bytes() noexcept {
    const volatile std::uint32_t* p = _ebss;
    while (p < _estack && *p == kPattern) ++p;
    return static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(_estack) -
                                    reinterpret_cast<std::uintptr_t>(p));
  }

 private:
  static constexpr std::uint32_t kPattern = 0xC0FFEE55U;
};

}  // namespace tread::firmware
