// The firmware image's main: runs the core on a fixed input so the linker keeps it all.
#include <array>
#include <cstdint>

#include "proto/crc8_j1850.hpp"

#ifdef TREAD_HEAP_PROBE
#include "core/heap_probe.hpp"
#endif

namespace {
volatile std::uint8_t g_sink;  // keeps the result observable
}

int main() {
  const std::array<std::uint8_t, 9> message{'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  g_sink = tread::proto::crc8_sae_j1850(message);
#ifdef TREAD_HEAP_PROBE
  g_sink = static_cast<std::uint8_t>(g_sink + tread::core_heap_probe());
#endif
  return 0;
}
