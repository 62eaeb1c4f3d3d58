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

include("${CMAKE_CURRENT_LIST_DIR}/checks.cmake")

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")

macro(run_tool)
  run_program("${GI_ACCURACY}" ${ARGN})
endmacro()

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
  expect_written("${images}/cornell_box_${name}" "--images" "stderr:\n${err}")
endforeach()
expect_png("${images}/cornell_box_regions.png")
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
