# AddressSanitizer + UndefinedBehaviorSanitizer; any report fails the run.
#
# Eigen under ASan: Eigen's headers switch to their own aligned allocator when __SANITIZE_ADDRESS__
# is defined, while the uninstrumented static Ceres library was built with glibc's malloc (already
# 16-byte aligned). Both copies of Eigen's inline allocation functions end up in one binary; the
# linker keeps ours for some calls and Ceres' inlined free for others, and frees mismatch
# (AddressSanitizer: bad-free in ceres::internal::CovarianceImpl). ASan's malloc is 16-byte aligned
# too (and Eigen asserts it in debug builds), so every unit uses malloc as Ceres does.
set(_tread_eigen_as_ceres EIGEN_MALLOC_ALREADY_ALIGNED=1)
if(TREAD_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
  add_compile_definitions(${_tread_eigen_as_ceres})
endif()

# libFuzzer (clang): every object instrumented for coverage and sanitized; the fuzz targets link the
# fuzzer's main (tests/fuzz).
if(TREAD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "TREAD_FUZZ needs clang (preset fuzz sets CMAKE_CXX_COMPILER=clang++)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_compile_definitions(${_tread_eigen_as_ceres})
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

# The sanitized build (preset asan) compiles at -O1, as AddressSanitizer's own documentation advises
# for a usable speed: its tests took 36 minutes at -O0 on a 2-core VM of this project's kind, 16 at
# -O1 (the fits' own sources: sim/fit/CMakeLists.txt). The test sources themselves compile at -O0
# (tests/CMakeLists.txt). A few of the tools' sources are one long generated function each (the
# X-macro code over every Magic Formula coefficient); with ASan, GCC takes minutes over each at -O1
# and seconds at -O0, and what runs from them is brief: they stay at -O0. Call from the directory
# that adds the source's target.
function(tread_sanitized_at_o0)
  if(TREAD_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -O0)
  endif()
endfunction()
