# Command-line test of lit-gi-accuracy, run by CTest as `cmake -P` (see tests/CMakeLists.txt).
# Inputs: GI_ACCURACY (the executable), SOURCE_DIR (the source tree), OUT_DIR (scratch folder).
#
# A tiny run on the Cornell box given with --scene writes its report and the --images files;
# bad command lines exit 2 with a message, and a misspelt --scenes name is refused rather than
# measuring nothing.

foreach(var GI_ACCURACY SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "gi_accuracy_cli.cmake needs -D${var}=...")
  endif()
endforeach()

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")

function(run_tool)
  execute_process(COMMAND "${GI_ACCURACY}" ${ARGN}
    RESULT_VARIABLE result OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr TIMEOUT 300)
  set(rc "${result}" PARENT_SCOPE)
  set(out "${stdout}" PARENT_SCOPE)
  set(err "${stderr}" PARENT_SCOPE)
endfunction()

# ---- A good run: report and images -------------------------------------------------------------
set(report "${OUT_DIR}/report.md")
set(images "${OUT_DIR}/images")
run_tool(--voxels 64 --spp 2 --size 64 --scene "${SOURCE_DIR}/assets/cornell_box.gltf" --images "${images}" --out "${report}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lit-gi-accuracy failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
file(READ "${report}" text)
foreach(row "| cornell_box | 64³ |" "| cornell_box | ceiling |" "| cornell_box | shadowed floor by red wall | R/G |")
  string(FIND "${text}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the report has no row starting \"${row}\":\n${text}")
  endif()
endforeach()
foreach(name reference_indirect.hdr vct64_indirect.hdr vct64_difference.png regions.png)
  set(file "${images}/cornell_box_${name}")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "--images did not write ${file}\nstderr:\n${err}")
  endif()
  file(SIZE "${file}" size)
  if(size EQUAL 0)
    message(FATAL_ERROR "--images wrote an empty ${file}")
  endif()
endforeach()
file(READ "${images}/cornell_box_regions.png" signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "cornell_box_regions.png is not a PNG file (starts with ${signature})")
endif()
file(READ "${images}/cornell_box_reference_indirect.hdr" signature LIMIT 16)
if(NOT signature MATCHES "^#\\?RADIANCE")
  message(FATAL_ERROR "cornell_box_reference_indirect.hdr is not a Radiance file (starts with ${signature})")
endif()

# ---- Bad command lines: exit 2 and say why -----------------------------------------------------
function(expect_refused expected)
  run_tool(${ARGN})
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "lit-gi-accuracy ${ARGN}: expected exit 2, got ${rc}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(NOT err MATCHES "${expected}")
    message(FATAL_ERROR "lit-gi-accuracy ${ARGN}: stderr does not say \"${expected}\":\n${err}")
  endif()
endfunction()
expect_refused("no scene called cornel_box" --scenes cornel_box)
expect_refused("no such file" --scene "${OUT_DIR}/missing.gltf")
expect_refused("--voxels" --voxels 100)
expect_refused("unknown option" --no-such-option 1)
expect_refused("missing value" --spp)

run_tool(--help)
if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: lit-gi-accuracy")
  message(FATAL_ERROR "lit-gi-accuracy --help: exit ${rc}, stdout:\n${out}")
endif()
