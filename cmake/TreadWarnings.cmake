# One warnings target for every toolchain (ARCHITECTURE.md, habit 3).
add_library(tread_warnings INTERFACE)
target_compile_options(tread_warnings INTERFACE
  -Wall -Wextra -Werror -Wshadow -Wconversion -Wsign-conversion -Wdouble-promotion -Wfloat-equal
  -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
  -Wimplicit-fallthrough -Wformat=2)

# The core: no exceptions, no RTTI. Applied to src/ and lut/ targets only.
add_library(tread_core_flags INTERFACE)
target_compile_options(tread_core_flags INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti> -fno-math-errno)
