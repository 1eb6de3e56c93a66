# Regenerates the default lookup tables and fails if they differ from lut/generated/.
execute_process(COMMAND ${GEN} ${ARGS} --output ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tread_lut_gen failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${EXPECTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${EXPECTED} differs from what the build generates (${OUT}); regenerate it")
endif()
message(STATUS "lookup tables reproduced byte for byte")
# Bad arguments are refused naming the option and the spec: none at all, a spec twice, an error
# bound that is not a number, a wheel the standard does not have (printed as written, not as the
# 309 digits of 1e308).
foreach(bad "--output;${OUT}.bad" "--profile;S1002;--profile;S1002;--output;${OUT}.bad"
            "--profile;S1002;--max-error-um;nan;--output;${OUT}.bad"
            "--profile;S1002:h=1e308;--output;${OUT}.bad")
  execute_process(COMMAND ${GEN} ${bad} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "tread_lut_gen ${bad}: accepted (want a refusal)")
  endif()
  if(NOT err MATCHES "(nothing to generate|given twice|--max-error-um: 'nan'|--profile 'S1002:h=1e308': flange height must be 28, 30 or 32 mm \\(EN 13715\\), got 1e\\+308)")
    message(FATAL_ERROR "tread_lut_gen ${bad}: unclear refusal '${err}'")
  endif()
endforeach()
