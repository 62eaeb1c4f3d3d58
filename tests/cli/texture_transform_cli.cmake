# lit-render on the KHR_texture_transform scene of tools/blender/make_texture_transform.py, run by
# CTest as `cmake -P` (see tests/CMakeLists.txt). Inputs: LIT_RENDER, SOURCE_DIR, OUT_DIR.
#
# The scene whose Mapping nodes Blender exported as KHR_texture_transform must render like its
# twin whose UVs the script baked: the rasterizer's image of the first against the second's, and
# the reference tracer's (no bounces) against the same, through `--compare`.

foreach(var LIT_RENDER SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "texture_transform_cli.cmake needs -D${var}=...")
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/checks.cmake")

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
set(dir "${SOURCE_DIR}/tests/data/blender/texture_transform")
set(common --size 128x64 --gi off)

# rmse_of(OUT VAR): the RMSE percentage of a --compare summary line.
function(rmse_of text var)
  if(NOT text MATCHES "RMSE ([0-9.]+) %")
    message(FATAL_ERROR "no --compare summary in lit-render's output:\n${text}")
  endif()
  set(${var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

run_program("${LIT_RENDER}" "${dir}/texture_transform_baked.gltf" ${common} --hdr "${OUT_DIR}/baked.hdr")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rendering the baked scene failed (exit ${rc})\n${out}\n${err}")
endif()
expect_written("${OUT_DIR}/baked.hdr" "lit-render" "${out}\n${err}")

# The baked scene against its own .hdr file: what the file's shared-exponent encoding alone
# costs (pure red and blue lose their small channels: about 4 %).
run_program("${LIT_RENDER}" "${dir}/texture_transform_baked.gltf" ${common} --compare "${OUT_DIR}/baked.hdr")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "comparing the baked scene with its own image failed (exit ${rc})\n${out}\n${err}")
endif()
rmse_of("${out}" encoding)

# The mapped scene: the same pixels but for float rounding at checker edges.
run_program("${LIT_RENDER}" "${dir}/texture_transform.gltf" ${common} --out "${OUT_DIR}/mapped.png"
  --compare "${OUT_DIR}/baked.hdr")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rendering the mapped scene failed (exit ${rc})\n${out}\n${err}")
endif()
rmse_of("${out}" raster)
# --compare prints one decimal: compare in tenths of a percent (CMake's math is integer).
string(REPLACE "." "" encoding_tenths "${encoding}")
string(REPLACE "." "" raster_tenths "${raster}")
math(EXPR limit_tenths "${encoding_tenths} + 5")
if(raster_tenths GREATER limit_tenths)
  message(FATAL_ERROR "the mapped scene differs from the baked one by RMSE ${raster} %, more than the "
                      "encoding's ${encoding} % + 0.5:\n${out}")
endif()

# The reference blends colours across checker edges inside a pixel and lights without shadow
# maps: 23 % at 4 spp. The scene with its transforms removed gives 72 % with either renderer.
run_program("${LIT_RENDER}" "${dir}/texture_transform.gltf" --size 128x64 --reference --bounces 0 --spp 4
  --out "${OUT_DIR}/mapped_reference.png" --compare "${OUT_DIR}/baked.hdr")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reference render of the mapped scene failed (exit ${rc})\n${out}\n${err}")
endif()
rmse_of("${out}" traced)
message(STATUS "mapped vs baked: rasterizer RMSE ${raster} % (encoding alone ${encoding} %), reference RMSE ${traced} %")
if(traced GREATER 40)
  message(FATAL_ERROR "the reference's image of the mapped scene differs from the baked scene's by RMSE ${traced} %:\n${out}")
endif()
