#pragma once
// Counts the heap allocations of a test program: replaces the global operator new/delete and, with
// glibc and without AddressSanitizer (which owns malloc), interposes malloc/calloc/realloc too.
// While tread::testing::g_counting is set, every allocation adds one to g_allocations (an operator
// new that calls malloc may count twice: any count above zero is an allocation). Include it in
// exactly ONE source file of a test program: it defines the replacements.

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace tread::testing {
inline std::atomic<bool> g_counting{false};
inline std::atomic<std::uint64_t> g_allocations{0};
inline void note_allocation() {
  if (g_counting.load(std::memory_order_relaxed)) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
  }
}
}  // namespace tread::testing

void* operator new(std::size_t size) {
  tread::testing::note_allocation();
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  tread::testing::note_allocation();
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

#if !defined(__SANITIZE_ADDRESS__)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t size) {
  tread::testing::note_allocation();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  tread::testing::note_allocation();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  tread::testing::note_allocation();
  return __libc_realloc(p, size);
}
}
#endif
