# Sources on `tread mf eval`'s per-row path (its CSV numbers read and written, its rows read and
# formatted) are compiled -O3 where the build is not instrumented: GCC then inlines fast_float's
# parse into the row reader and Dragonbox's digits into the writer. The sanitized and fuzzing
# builds keep their own level. What it gained: docs/performance.md, "`tread mf eval`'s row path
# at -O3".
# Call from the directory that adds the sources' target.
function(tread_hot_sources)
  if(NOT TREAD_SANITIZE AND NOT TREAD_FUZZ)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -O3)
  endif()
endfunction()
