#pragma once
// Arm semihosting (the debugger's, or qemu-system-arm's `-semihosting-config enable=on`): the
// target's files, console, command line and exit status go through `bkpt 0xAB` to the host. Raw
// calls only — no newlib stdio (it allocates; the image keeps the no-heap trap). Cortex-M only.
// Every call blocks until the host answers; use it outside the timed path.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "core/status.hpp"

namespace tread::hal::semihost {

/// A host file handle (≥ 0 when open).
struct Handle {
  std::int32_t value{-1};
};

enum class Mode : std::uint32_t {
  read_binary = 1,   ///< "rb"
  write_binary = 5,  ///< "wb": create or truncate
};

/// SYS_OPEN. `path` need not be '\0'-terminated (it is copied, at most kMaxPath - 1 characters).
/// @retval Status::invalid_argument  the path is empty or too long
/// @retval Status::io_error          the host could not open it
inline constexpr std::size_t kMaxPath = 256;
Result<Handle> open(std::string_view path, Mode mode) noexcept;

/// SYS_CLOSE.
/// @retval Status::io_error  the host refused
Status close(Handle file) noexcept;

/// SYS_READ into `buffer`: the number of bytes read (0 at the end of the file).
/// @retval Status::io_error  the host could not read
Result<std::size_t> read(Handle file, std::span<char> buffer) noexcept;

/// SYS_WRITE of all of `bytes`.
/// @retval Status::io_error  the host wrote fewer bytes
Status write(Handle file, std::span<const char> bytes) noexcept;

/// SYS_FLEN: the file's length in bytes.
/// @retval Status::io_error  the host could not tell
Result<std::size_t> length(Handle file) noexcept;

/// SYS_GET_CMDLINE into `buffer` ('\0'-terminated): qemu's `-semihosting-config arg=...` words,
/// separated by spaces. Returns the length.
/// @retval Status::io_error  the host has none or it does not fit
Result<std::size_t> command_line(std::span<char> buffer) noexcept;

/// SYS_WRITE0: a '\0'-terminated string to the host's console.
void console(const char* text) noexcept;

/// SYS_EXIT_EXTENDED (ADP_Stopped_ApplicationExit with `status`): qemu exits with `status`.
[[noreturn]] void exit(int status) noexcept;

}  // namespace tread::hal::semihost
