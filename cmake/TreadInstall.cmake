# `cmake --install`: the core as a CMake package, so an ECU team's project writes
#   find_package(tread REQUIRED)
#   target_link_libraries(app PRIVATE tread::lut tread::core)
# and includes the headers as the tree does ("mf/mf_evaluate.hpp", "lut/tread_lut.hpp",
# "hal_concepts.hpp"). examples/consumer is such a project; scripts/check-install.sh builds it
# against the installed host and Cortex-M4F packages.
#
# Exported targets (namespace tread::):
#   core            src/ (static library)
#   lut             the tables of this build (TREAD_LUT_PROFILES / TREAD_LUT_CONTACT_PAIRS)
#   hal             the HAL concepts and the loop runner (header-only, hal/hal_concepts.hpp, hal/loop/)
#   hal_<backend>   each backend of TREAD_HAL_BACKENDS (socketcan, gpiod, posix, stub)
#   core_flags      optional: the flags the core is compiled with (-fno-math-errno, and for C++
#                   -fno-exceptions -fno-rtti), for consumers who want their code built the same way.
# The warnings target and the core's flags are build-only requirements of core and lut (wrapped in
# $<BUILD_INTERFACE:...>): consuming the package does not impose them. The CPU flags are not
# exported either: they come from the toolchain (cmake/cpu/*.cmake); the package records them and
# refuses a consumer configured without them (tread-config.cmake).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TREAD_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/tread)
set(TREAD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tread)
set(TREAD_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/tread)

set(_tread_export_targets tread_core tread_lut tread_hal_interface tread_core_flags)
set_target_properties(tread_core PROPERTIES EXPORT_NAME core)
set_target_properties(tread_lut PROPERTIES EXPORT_NAME lut)
set_target_properties(tread_hal_interface PROPERTIES EXPORT_NAME hal)
set_target_properties(tread_core_flags PROPERTIES EXPORT_NAME core_flags)
set(_tread_components core lut hal core_flags)
foreach(backend IN LISTS TREAD_HAL_BACKENDS)
  list(APPEND _tread_export_targets tread_hal_${backend})
  list(APPEND _tread_components hal_${backend})
  set_target_properties(tread_hal_${backend} PROPERTIES EXPORT_NAME hal_${backend})
endforeach()

# The warnings and the core's flags are build-only: a library that links them plainly
# (PRIVATE tread_warnings, as a new HAL backend may) is given $<BUILD_INTERFACE:...> here, so the
# export never asks a consumer for them.
foreach(target IN LISTS _tread_export_targets)
  get_target_property(_tread_libs ${target} INTERFACE_LINK_LIBRARIES)
  if(_tread_libs)
    list(TRANSFORM _tread_libs REPLACE "^\\$<LINK_ONLY:(tread_warnings|tread_core_flags)>$"
                                       "$<LINK_ONLY:$<BUILD_INTERFACE:\\1>>")
    set_property(TARGET ${target} PROPERTY INTERFACE_LINK_LIBRARIES "${_tread_libs}")
  endif()
endforeach()

foreach(target IN LISTS _tread_export_targets)
  if(target STREQUAL "tread_core_flags")
    continue()
  endif()
  target_include_directories(${target} INTERFACE $<INSTALL_INTERFACE:${TREAD_INSTALL_INCLUDEDIR}>)
endforeach()

install(TARGETS ${_tread_export_targets} EXPORT tread-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT tread-targets NAMESPACE tread:: DESTINATION ${TREAD_INSTALL_CMAKEDIR})

# Headers, at the paths the tree includes them by (one include directory: include/tread).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${TREAD_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_SOURCE_DIR}/lut/tread_lut.hpp DESTINATION ${TREAD_INSTALL_INCLUDEDIR}/lut)
install(FILES ${PROJECT_SOURCE_DIR}/hal/hal_concepts.hpp DESTINATION ${TREAD_INSTALL_INCLUDEDIR})
foreach(dir IN LISTS TREAD_HAL_BACKENDS ITEMS loop)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/hal/${dir} DESTINATION ${TREAD_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

# What a consumer needs besides headers and libraries: the CAN databases of the protocol, and the
# toolchain and CPU files the package was built with (to configure a cross consumer the same way).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/proto/ DESTINATION ${TREAD_INSTALL_DATADIR}/dbc
        FILES_MATCHING PATTERN "*.dbc")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/toolchains/ DESTINATION ${TREAD_INSTALL_DATADIR}/toolchains
        FILES_MATCHING PATTERN "*.cmake")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cmake/cpu/ DESTINATION ${TREAD_INSTALL_DATADIR}/cpu
        FILES_MATCHING PATTERN "*.cmake")

# The package config: what this build was made for, checked against the consumer.
if(DEFINED TREAD_CPU_FLAGS)
  set(TREAD_PACKAGE_CPU_FLAGS "${TREAD_CPU_FLAGS}")
else()
  set(TREAD_PACKAGE_CPU_FLAGS "")
endif()
if(TREAD_CPU_FILE)
  get_filename_component(TREAD_PACKAGE_CPU_FILE "${TREAD_CPU_FILE}" NAME)
else()
  set(TREAD_PACKAGE_CPU_FILE "")
endif()
if(CMAKE_TOOLCHAIN_FILE)
  get_filename_component(TREAD_PACKAGE_TOOLCHAIN_FILE "${CMAKE_TOOLCHAIN_FILE}" NAME)
else()
  set(TREAD_PACKAGE_TOOLCHAIN_FILE "")
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/tread-config.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/tread-config.cmake
  INSTALL_DESTINATION ${TREAD_INSTALL_CMAKEDIR}
  PATH_VARS TREAD_INSTALL_DATADIR)
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/tread-config-version.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tread-config.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/tread-config-version.cmake
        DESTINATION ${TREAD_INSTALL_CMAKEDIR})

# Everything `cmake --install` copies, so a script can build just that (scripts/check-install.sh).
add_custom_target(tread_package DEPENDS ${_tread_export_targets})
