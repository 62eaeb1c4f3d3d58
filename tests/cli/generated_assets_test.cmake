# The committed generated scenes must be what their generators write today (ctest
# generated_assets): assets/cornell_box.* from make-cornell-box and assets/gi/* from make-gi-suite.
# A generator changed without re-running it leaves tests and benchmarks measuring a stale scene
# (lights written in radiometric rather than photometric glTF units are 683× too dim; docs/UNITS.md).
#   cmake -DMAKE_CORNELL_BOX=... -DMAKE_GI_SUITE=... -DSOURCE_DIR=... -DOUT_DIR=... -P generated_assets_test.cmake
foreach(var MAKE_CORNELL_BOX MAKE_GI_SUITE SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "generated_assets_test.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}/cornell" "${OUT_DIR}/gi")

function(generate tool dir)
  execute_process(COMMAND "${tool}" "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${tool} ${dir} failed (${rc}):\n${out}${err}")
  endif()
endfunction()
generate("${MAKE_CORNELL_BOX}" "${OUT_DIR}/cornell")
generate("${MAKE_GI_SUITE}" "${OUT_DIR}/gi")

set(stale "")
function(compare generated committed)
  if(NOT EXISTS "${committed}")
    set(stale "${stale}\n  ${committed} (missing; the generator writes it)" PARENT_SCOPE)
    return()
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${generated}" "${committed}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    set(stale "${stale}\n  ${committed}" PARENT_SCOPE)
  endif()
endfunction()

file(GLOB cornell RELATIVE "${OUT_DIR}/cornell" "${OUT_DIR}/cornell/*")
foreach(f IN LISTS cornell)
  compare("${OUT_DIR}/cornell/${f}" "${SOURCE_DIR}/assets/${f}")
endforeach()
file(GLOB suite RELATIVE "${OUT_DIR}/gi" "${OUT_DIR}/gi/*")
list(LENGTH suite count)
if(count LESS 2)
  message(FATAL_ERROR "make-gi-suite wrote ${count} files into ${OUT_DIR}/gi; expected the suite's scenes")
endif()
foreach(f IN LISTS suite)
  compare("${OUT_DIR}/gi/${f}" "${SOURCE_DIR}/assets/gi/${f}")
endforeach()

if(NOT stale STREQUAL "")
  message(FATAL_ERROR "committed assets differ from their generators' output:${stale}\n"
                      "Regenerate and commit them: build/tools/make-cornell-box assets; build/tools/make-gi-suite assets/gi")
endif()
message(STATUS "generated assets match: ${SOURCE_DIR}/assets (cornell_box) and assets/gi (${count} files)")
