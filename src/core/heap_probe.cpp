#include "core/heap_probe.hpp"

namespace tread {
namespace {
int* volatile g_escape = nullptr;  // the allocation escapes, so the compiler may not elide it
}

int core_heap_probe() {
  g_escape = new int(42);  // deliberate: the firmware link must reject this
  const int result = *g_escape;
  delete g_escape;
  return result;
}

}  // namespace tread
