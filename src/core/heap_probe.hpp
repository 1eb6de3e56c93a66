#pragma once
// Built only with -DTREAD_HEAP_PROBE=ON: a deliberate heap allocation inside the core, used to show
// that the Cortex-M firmware link fails when anything in the core references operator new.

namespace tread {
int core_heap_probe();
}
