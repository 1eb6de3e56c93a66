# Regenerates a DBC with `tread proto dbc` and fails if it differs from the file in the repo.
execute_process(COMMAND ${TREAD} proto dbc --layout ${LAYOUT} --output ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tread proto dbc failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${EXPECTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${EXPECTED} is out of date: run `tread proto dbc --layout ${LAYOUT} --output ${EXPECTED}`")
endif()
message(STATUS "${EXPECTED} matches the codec tables")
# The layout is given by name: the enum's numbers ("1") are refused, as is any other word.
foreach(bad 1 0 classical)
  execute_process(COMMAND ${TREAD} proto dbc --layout ${bad} RESULT_VARIABLE rc OUTPUT_QUIET
                  ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "--layout: ${bad} not in {classic,fd}")
    message(FATAL_ERROR "tread proto dbc --layout ${bad}: exit ${rc}, '${err}' (want a refusal)")
  endif()
endforeach()
