// Minimal Cortex-M startup: vector table, .data copy, .bss clear, static constructors, main().
#include <cstddef>
#include <cstdint>

extern "C" {
extern std::uint32_t _sidata[];
extern std::uint32_t _sdata[];
extern std::uint32_t _edata[];
extern std::uint32_t _sbss[];
extern std::uint32_t _ebss[];
extern std::uint32_t _estack[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();

int main();
[[noreturn]] void Reset_Handler();
void Default_Handler();
}

namespace {
constexpr std::size_t kCoreVectors = 16;
using Vector = void (*)();
}  // namespace

#if defined(__ARM_FP)
// SCB->CPACR: enable CP10/CP11 (the FPU) before any float instruction runs.
static void enable_fpu() {
  volatile std::uint32_t* const cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88U);
  *cpacr = *cpacr | (0xFU << 20U);
  __asm volatile("dsb\n\tisb" ::: "memory");
}
#endif

extern "C" [[noreturn]] void Reset_Handler() {
#if defined(__ARM_FP)
  enable_fpu();
#endif
  const std::uint32_t* src = _sidata;
  for (std::uint32_t* dst = _sdata; dst < _edata;) {
    *dst++ = *src++;
  }
  for (std::uint32_t* dst = _sbss; dst < _ebss;) {
    *dst++ = 0U;
  }
  for (void (**ctor)() = __init_array_start; ctor < __init_array_end; ++ctor) {
    (*ctor)();
  }
  static_cast<void>(main());
  for (;;) {
    __asm volatile("wfi");
  }
}

extern "C" void Default_Handler() {
  for (;;) {
  }
}

__attribute__((section(".isr_vector"), used)) const Vector kVectorTable[kCoreVectors] = {
    reinterpret_cast<Vector>(_estack),  // initial stack pointer
    Reset_Handler,
    Default_Handler,
    Default_Handler,
    Default_Handler,
    Default_Handler,
    Default_Handler,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    Default_Handler,
    Default_Handler,
    nullptr,
    Default_Handler,
    Default_Handler,
};
