# `cmake --install` into a fresh prefix, then lit-render run from there must find its shaders and
# the Cornell box under PREFIX/share/lit (not through the source tree it was built from).
# Run by CTest as `cmake -P`; inputs: BUILD_DIR (the build tree), OUT_DIR (scratch folder).
foreach(var BUILD_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_test.cmake needs -D${var}=...")
  endif()
endforeach()

set(prefix "${OUT_DIR}/prefix")
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}\n${err}")
endif()
foreach(file bin/lit-render share/lit/shaders/gbuffer.vert.glsl share/lit/shaders/include/shared.h
        share/lit/assets/cornell_box.gltf share/lit/assets/cornell_box.bin)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()
if(EXISTS "${BUILD_DIR}/editor/lit-editor" AND NOT EXISTS "${prefix}/bin/lit-editor")
  message(FATAL_ERROR "cmake --install did not install lit-editor")
endif()

# Without the development overrides, from a folder that is neither the source nor the build tree.
set(png "${OUT_DIR}/installed.png")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=LIT_SHADER_DIR --unset=LIT_ASSET_DIR
    "${prefix}/bin/lit-render" "${prefix}/share/lit/assets/cornell_box.gltf" --out "${png}" --size 32x32 --gi off
  WORKING_DIRECTORY "${OUT_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0 OR NOT EXISTS "${png}")
  message(FATAL_ERROR "the installed lit-render failed (${rc}):\n${out}\n${err}")
endif()
file(REAL_PATH "${prefix}/share/lit/shaders" shaders)
if(NOT err MATCHES "shaders from ${shaders}")
  message(FATAL_ERROR "the installed lit-render did not use the installed shaders (${shaders}):\n${err}")
endif()

# The documented override still wins.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env LIT_SHADER_DIR=${OUT_DIR}/no_such_folder
    "${prefix}/bin/lit-render" "${prefix}/share/lit/assets/cornell_box.gltf" --out "${OUT_DIR}/never.png" --size 16x16 --gi off
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(rc EQUAL 0 OR NOT err MATCHES "no_such_folder")
  message(FATAL_ERROR "LIT_SHADER_DIR was not used (exit ${rc}):\n${err}")
endif()
message(STATUS "installed into ${prefix}; lit-render ran from there")
