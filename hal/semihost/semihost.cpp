#include "semihost/semihost.hpp"

#include <array>

namespace tread::hal::semihost {
namespace {

// Operation numbers of the Arm semihosting specification.
enum Op : std::uint32_t {
  kSysOpen = 0x01,
  kSysClose = 0x02,
  kSysWrite0 = 0x04,
  kSysWrite = 0x05,
  kSysRead = 0x06,
  kSysFlen = 0x0C,
  kSysGetCmdline = 0x15,
  kSysExit = 0x18,
  kSysExitExtended = 0x20,
};
constexpr std::uintptr_t kAdpStoppedApplicationExit = 0x20026;

/// The semihosting trap: r0 = operation, r1 = its argument (usually a parameter block); r0 =
/// result. `memory` clobber: the host reads and writes the blocks and buffers.
std::int32_t call(std::uint32_t op, const void* arg) noexcept {
  register std::uint32_t r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return static_cast<std::int32_t>(r0);
}

std::uintptr_t word(const void* p) noexcept {
  return reinterpret_cast<std::uintptr_t>(p);
}

}  // namespace

Result<Handle> open(std::string_view path, Mode mode) noexcept {
  std::array<char, kMaxPath> name{};
  if (path.empty() || path.size() >= name.size()) {
    return {{}, Status::invalid_argument};
  }
  for (std::size_t i = 0; i < path.size(); ++i) {
    name[i] = path[i];
  }
  const std::array<std::uintptr_t, 3> block{word(name.data()), static_cast<std::uintptr_t>(mode),
                                            path.size()};
  const std::int32_t h = call(kSysOpen, block.data());
  if (h < 0) {
    return {{}, Status::io_error};
  }
  return {Handle{h}, Status::ok};
}

Status close(Handle file) noexcept {
  const std::array<std::uintptr_t, 1> block{static_cast<std::uintptr_t>(file.value)};
  return call(kSysClose, block.data()) == 0 ? Status::ok : Status::io_error;
}

Result<std::size_t> read(Handle file, std::span<char> buffer) noexcept {
  const std::array<std::uintptr_t, 3> block{static_cast<std::uintptr_t>(file.value),
                                            word(buffer.data()), buffer.size()};
  // The result is the number of bytes NOT read.
  const std::int32_t left = call(kSysRead, block.data());
  if (left < 0 || static_cast<std::size_t>(left) > buffer.size()) {
    return {0, Status::io_error};
  }
  return {buffer.size() - static_cast<std::size_t>(left), Status::ok};
}

Status write(Handle file, std::span<const char> bytes) noexcept {
  const std::array<std::uintptr_t, 3> block{static_cast<std::uintptr_t>(file.value),
                                            word(bytes.data()), bytes.size()};
  // The result is the number of bytes NOT written.
  return call(kSysWrite, block.data()) == 0 ? Status::ok : Status::io_error;
}

Result<std::size_t> length(Handle file) noexcept {
  const std::array<std::uintptr_t, 1> block{static_cast<std::uintptr_t>(file.value)};
  const std::int32_t n = call(kSysFlen, block.data());
  if (n < 0) {
    return {0, Status::io_error};
  }
  return {static_cast<std::size_t>(n), Status::ok};
}

Result<std::size_t> command_line(std::span<char> buffer) noexcept {
  if (buffer.empty()) {
    return {0, Status::io_error};
  }
  // In: buffer and its size; out: the length written back into the block.
  std::array<std::uintptr_t, 2> block{word(buffer.data()), buffer.size()};
  if (call(kSysGetCmdline, block.data()) != 0 || block[1] >= buffer.size()) {
    return {0, Status::io_error};
  }
  buffer[block[1]] = '\0';
  return {block[1], Status::ok};
}

void console(const char* text) noexcept {
  static_cast<void>(call(kSysWrite0, text));
}

void exit(int status) noexcept {
  const std::array<std::uintptr_t, 2> block{kAdpStoppedApplicationExit,
                                            static_cast<std::uintptr_t>(status)};
  static_cast<void>(call(kSysExitExtended, block.data()));
  // A host without SYS_EXIT_EXTENDED: the plain exit (status lost unless 0).
  static_cast<void>(call(kSysExit, reinterpret_cast<const void*>(kAdpStoppedApplicationExit)));
  for (;;) {
  }
}

}  // namespace tread::hal::semihost
