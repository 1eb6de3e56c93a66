# `format-check` fails on any file clang-format would change; `format` rewrites them.
find_program(CLANG_FORMAT_EXE NAMES clang-format clang-format-14)
if(CLANG_FORMAT_EXE)
  file(GLOB_RECURSE _tread_fmt_files CONFIGURE_DEPENDS
       ${PROJECT_SOURCE_DIR}/src/*.hpp ${PROJECT_SOURCE_DIR}/src/*.cpp
       ${PROJECT_SOURCE_DIR}/hal/*.hpp ${PROJECT_SOURCE_DIR}/hal/*.cpp
       ${PROJECT_SOURCE_DIR}/sim/*.hpp ${PROJECT_SOURCE_DIR}/sim/*.cpp
       ${PROJECT_SOURCE_DIR}/tests/*.hpp ${PROJECT_SOURCE_DIR}/tests/*.cpp
       ${PROJECT_SOURCE_DIR}/firmware/*.hpp ${PROJECT_SOURCE_DIR}/firmware/*.cpp
       ${PROJECT_SOURCE_DIR}/examples/*.hpp ${PROJECT_SOURCE_DIR}/examples/*.cpp
       ${PROJECT_SOURCE_DIR}/lut/*.hpp ${PROJECT_SOURCE_DIR}/lut/*.cpp)
  list(FILTER _tread_fmt_files EXCLUDE REGEX "/(lut|firmware)/generated/")
  add_custom_target(format-check
    COMMAND ${CLANG_FORMAT_EXE} --dry-run --Werror ${_tread_fmt_files}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} COMMENT "clang-format check" VERBATIM)
  add_custom_target(format
    COMMAND ${CLANG_FORMAT_EXE} -i ${_tread_fmt_files}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} COMMENT "clang-format" VERBATIM)
endif()
