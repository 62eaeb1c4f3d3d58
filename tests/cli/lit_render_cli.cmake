# Command-line tests of lit-render, run by CTest as `cmake -P` (see tests/CMakeLists.txt).
# Inputs: LIT_RENDER (the executable), SOURCE_DIR (the source tree), OUT_DIR (scratch folder).
#
# One good render of the Cornell box, then every kind of bad input must fail with a non-zero
# exit status and a message on stderr — never a crash, never silence.

foreach(var LIT_RENDER SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "lit_render_cli.cmake needs -D${var}=...")
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/checks.cmake")

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
set(cornell "${SOURCE_DIR}/assets/cornell_box.gltf")

# Runs lit-render with the given arguments; sets rc, out and err in the caller's scope.
macro(run_lit_render)
  run_program("${LIT_RENDER}" ${ARGN})
endmacro()

# ---- A good render ----------------------------------------------------------------------------
set(png "${OUT_DIR}/cornell.png")
set(hdr "${OUT_DIR}/cornell.hdr")
run_lit_render("${cornell}" --out "${png}" --hdr "${hdr}" --size 64x64 --single-frame)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rendering the Cornell box failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
foreach(file "${png}" "${hdr}")
  expect_written("${file}" "lit-render (exit 0)" "stdout:\n${out}\nstderr:\n${err}")
endforeach()
expect_png("${png}")
if(NOT out MATCHES "wrote .*cornell\\.png")
  message(FATAL_ERROR "lit-render printed no summary line; stdout:\n${out}")
endif()
foreach(tmp "${png}.tmp" "${hdr}.tmp")
  if(EXISTS "${tmp}")
    message(FATAL_ERROR "lit-render left its temporary file ${tmp} behind")
  endif()
endforeach()

# ---- A reference render (CPU path tracer) ------------------------------------------------------
set(ref_png "${OUT_DIR}/reference.png")
set(ref_hdr "${OUT_DIR}/reference.hdr")
run_lit_render("${cornell}" --reference --spp 2 --size 32x32 --out "${ref_png}" --hdr "${ref_hdr}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reference render failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
foreach(file "${ref_png}" "${ref_hdr}")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "lit-render --reference exited 0 but did not write ${file}")
  endif()
endforeach()
if(NOT out MATCHES "reference: 32x32, 2 spp .* Mrays/s")
  message(FATAL_ERROR "lit-render --reference printed no rays/s summary; stdout:\n${out}")
endif()

# ---- Comparing with the reference: a self-comparison is exact, a wrong reference is refused ----
set(diff_png "${OUT_DIR}/difference.png")
run_lit_render("${cornell}" --reference --spp 2 --size 32x32 --compare "${ref_hdr}" --difference "${diff_png}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--compare of the reference with itself failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
# The image compared is the float render; the reference its .hdr file, whose RGBE encoding keeps
# 8 bits of mantissa (up to ~0.8 % per channel): ratio within 1 %, RMSE below 2 %.
if(NOT out MATCHES "compare with [^\n]*reference\\.hdr: mean luminance [0-9.e-]+ against [0-9.e-]+ \\(ratio (1\\.00|0\\.99)[0-9]\\), RMSE [01]\\.[0-9] %")
  message(FATAL_ERROR "the same image compared with itself should give a ratio within 1 % of 1 and an RMSE below 2 %; stdout:\n${out}")
endif()
if(NOT EXISTS "${diff_png}")
  message(FATAL_ERROR "--difference did not write ${diff_png}")
endif()

# ---- Bad inputs -------------------------------------------------------------------------------
# expect_failure(NAME EXPECTED_RC STDERR_REGEX ARGS...): EXPECTED_RC is 1 (runtime) or 2 (bad
# input: the command line, the scene, settings or path file, the output folder, the size).
function(expect_failure name expected_rc stderr_regex)
  run_lit_render(${ARGN})
  if(rc EQUAL 0)
    message(FATAL_ERROR "${name}: lit-render succeeded but should have failed\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(NOT rc STREQUAL "${expected_rc}")
    message(FATAL_ERROR "${name}: expected exit status ${expected_rc}, got '${rc}' (a crash?)\nstderr:\n${err}")
  endif()
  if(err STREQUAL "")
    message(FATAL_ERROR "${name}: lit-render failed without a message on stderr")
  endif()
  # The error itself is one line (the usage summary may follow it).
  string(REGEX MATCH "lit-render: [^\n]*\n" first_error "${err}")
  if(first_error STREQUAL "")
    message(FATAL_ERROR "${name}: no 'lit-render: ...' error line on stderr:\n${err}")
  endif()
  if(NOT err MATCHES "${stderr_regex}")
    message(FATAL_ERROR "${name}: stderr does not match '${stderr_regex}':\n${err}")
  endif()
  message(STATUS "${name}: exit ${rc}, stderr: ${err}")
endfunction()

set(not_gltf "${OUT_DIR}/not_a_scene.gltf")
file(WRITE "${not_gltf}" "This is a text file, not glTF.\n")

expect_failure("missing scene file" 2 "cannot load .*does_not_exist\\.gltf"
  "${OUT_DIR}/does_not_exist.gltf" --out "${OUT_DIR}/a.png" --size 16x16)
expect_failure("non-glTF file" 2 "cannot load .*not_a_scene\\.gltf"
  "${not_gltf}" --out "${OUT_DIR}/b.png" --size 16x16)
expect_failure("bad --size" 2 "--size expects WxH with 1\\.\\.16384, got '12x'"
  "${cornell}" --out "${OUT_DIR}/c.png" --size 12x)
expect_failure("unknown flag" 2 "unknown option '--sparkles'"
  "${cornell}" --out "${OUT_DIR}/d.png" --sparkles)
expect_failure("unknown view" 2 "unknown view 'xray'"
  "${cornell}" --out "${OUT_DIR}/e.png" --view xray)
expect_failure("unknown camera" 2 "unknown camera 'nowhere'.*'camera'"
  "${cornell}" --out "${OUT_DIR}/f.png" --size 16x16 --camera nowhere)

# ---- Hostile and out-of-range inputs: each a one-line error, exit 2, nothing written
file(MAKE_DIRECTORY "${OUT_DIR}/a_folder.gltf")
expect_failure("a folder as the scene" 2 "a_folder\\.gltf: is a directory"
  "${OUT_DIR}/a_folder.gltf" --out "${OUT_DIR}/g.png" --size 16x16)
file(WRITE "${OUT_DIR}/empty.gltf" "")
expect_failure("an empty scene" 2 "empty\\.gltf: the file is empty"
  "${OUT_DIR}/empty.gltf" --out "${OUT_DIR}/h.png" --size 16x16)
expect_failure("a device as the scene" 2 "not a regular file"
  "/dev/zero" --out "${OUT_DIR}/i.png" --size 16x16)
file(READ "${cornell}" cornell_json)
string(REPLACE "\"version\": \"2.0\"" "\"version\": \"3.0\"" v3_json "${cornell_json}")
file(WRITE "${OUT_DIR}/v3.gltf" "${v3_json}")
file(COPY "${SOURCE_DIR}/assets/cornell_box.bin" DESTINATION "${OUT_DIR}")
expect_failure("glTF 3.0" 2 "asset.version is '3.0'; Lit reads glTF 2.x only"
  "${OUT_DIR}/v3.gltf" --out "${OUT_DIR}/j.png" --size 16x16)
string(REPLACE "\"uri\": \"cornell_box.bin\"" "\"uri\": \"../../../../etc/passwd\"" escape_json "${cornell_json}")
file(WRITE "${OUT_DIR}/escape.gltf" "${escape_json}")
expect_failure("a buffer outside the scene's folder" 2 "points outside the scene's folder"
  "${OUT_DIR}/escape.gltf" --out "${OUT_DIR}/k.png" --size 16x16)
# An absolute file: URI: refused without the opt-in, read with it (tinygltf would join it onto
# the scene's folder; GltfGuard maps it back).
file(MAKE_DIRECTORY "${OUT_DIR}/absolute")
string(REPLACE "\"uri\": \"cornell_box.bin\"" "\"uri\": \"file://${OUT_DIR}/cornell_box.bin\"" absolute_json "${cornell_json}")
file(WRITE "${OUT_DIR}/absolute/absolute.gltf" "${absolute_json}")
expect_failure("a file: URI without --allow-external-uris" 2 "points outside the scene's folder.*--allow-external-uris"
  "${OUT_DIR}/absolute/absolute.gltf" --out "${OUT_DIR}/absolute/refused.png" --size 16x16)
run_lit_render("${OUT_DIR}/absolute/absolute.gltf" --allow-external-uris --out "${OUT_DIR}/absolute/read.png" --size 16x16
  --single-frame)
if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT_DIR}/absolute/read.png")
  message(FATAL_ERROR "a file: URI with --allow-external-uris did not render (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
foreach(size 0x16 -5x16 16x99999 99999999999x2)
  expect_failure("--size ${size}" 2 "--size expects WxH" "${cornell}" --out "${OUT_DIR}/l.png" --size ${size})
endforeach()
foreach(voxels 0 -64 100 1024 99999999999)
  expect_failure("--voxels ${voxels}" 2 "--voxels expects a power of two" "${cornell}" --out "${OUT_DIR}/m.png" --voxels ${voxels})
endforeach()
file(WRITE "${OUT_DIR}/zero_width.json" "{\"width\": 0}")
expect_failure("settings width 0" 2 "width is 0, expected 1\\.\\.16384"
  "${cornell}" --out "${OUT_DIR}/n.png" --settings "${OUT_DIR}/zero_width.json")
file(WRITE "${OUT_DIR}/huge_height.json" "{\"height\": 1000000}")
expect_failure("settings height 1000000" 2 "height is 1000000"
  "${cornell}" --out "${OUT_DIR}/n.png" --settings "${OUT_DIR}/huge_height.json")
file(WRITE "${OUT_DIR}/bad_voxels.json" "{\"voxelResolution\": 100}")
expect_failure("settings voxelResolution 100" 2 "voxelResolution is 100"
  "${cornell}" --out "${OUT_DIR}/n.png" --settings "${OUT_DIR}/bad_voxels.json")
file(WRITE "${OUT_DIR}/not_json.json" "{\"width\": ")
expect_failure("settings that are not JSON" 2 "cannot use settings .*not_json\\.json"
  "${cornell}" --out "${OUT_DIR}/n.png" --settings "${OUT_DIR}/not_json.json")
expect_failure("missing settings" 2 "cannot read settings .*no_settings\\.json"
  "${cornell}" --out "${OUT_DIR}/n.png" --settings "${OUT_DIR}/no_settings.json")
expect_failure("output under a file" 2 "cannot create the folder /dev/null"
  "${cornell}" --out "/dev/null/o.png" --size 16x16)
file(MAKE_DIRECTORY "${OUT_DIR}/folder.png")
expect_failure("output is a folder" 2 "is a folder, not a file"
  "${cornell}" --out "${OUT_DIR}/folder.png" --size 16x16)
expect_failure("output folder not writable" 2 "cannot create the folder /proc/lit"
  "${cornell}" --out "/proc/lit/p.png" --size 16x16)
# The memory a scene and its render need is estimated before any of it is allocated, by the
# loader's accounting (scene/SceneMemory.h); LIT_MAX_RENDER_MB caps what the machine has, so the
# test does not depend on this machine's memory.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env LIT_MAX_RENDER_MB=100
    "${LIT_RENDER}" "${cornell}" --out "${OUT_DIR}/q.png" --size 4096x4096 --gi off
  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 2 OR NOT err MATCHES
    "scene needs 1\\.[0-9] GB of memory \\(render targets 1\\.3 GB, .*\\), over the limit of 100\\.0 MB \\(LIT_MAX_RENDER_MB\\)")
  message(FATAL_ERROR "a render over the memory cap: exit ${rc}\n${err}")
endif()

# A GL error during a render makes lit-render exit 1 with a message and write nothing (not exit 0
# with the error only in the log, and a wrong image). LIT_TEST_GL_ERROR=1 makes one
# invalid GL call after the frames (gl::injectGlErrorIfRequested), caught by the same debug
# output a driver or pass error would reach. A 16x16 render without GI: about a second.
set(gl_error_png "${OUT_DIR}/gl_error.png")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env LIT_TEST_GL_ERROR=1
    "${LIT_RENDER}" "${cornell}" --out "${gl_error_png}" --size 16x16 --gi off
  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 1 OR NOT err MATCHES "lit: error: GL error \\(api" OR NOT err MATCHES
   "lit-render: 1 GL error during the render \\(see above\\); nothing was written")
  message(FATAL_ERROR "a GL error during the render: exit ${rc} (expected 1 and both messages)\n${err}")
endif()
if(EXISTS "${gl_error_png}" OR EXISTS "${gl_error_png}.tmp")
  message(FATAL_ERROR "lit-render wrote ${gl_error_png} although the render had a GL error")
endif()

# Unknown keys and clamped values in a settings file are warnings, and the render goes on.
file(WRITE "${OUT_DIR}/odd.json" "{\"sparkles\": 3, \"specularSamples\": 50, \"gi\": false, \"width\": 16, \"height\": 16}")
run_lit_render("${cornell}" --out "${OUT_DIR}/odd.png" --settings "${OUT_DIR}/odd.json")
if(NOT rc EQUAL 0 OR NOT err MATCHES "unknown setting 'sparkles' ignored" OR NOT err MATCHES "specularSamples 50 is outside 1\\.\\.8; using 8")
  message(FATAL_ERROR "settings with an unknown key and a clamped value: exit ${rc}\n${err}")
endif()

# --set KEY=VALUE: an older key is read with its deprecation warning; a value lit-render clamps is
# a warning and the render goes on; a size it cannot render is refused before any GL work.
run_lit_render("${cornell}" --out "${OUT_DIR}/set.png" --size 16x16 --set gi.enabled=false --set width=8
  --set debug.voxelSlice=2)
if(NOT rc EQUAL 0 OR NOT err MATCHES "--set: render settings: 'width' is deprecated; read as output\\.width"
   OR NOT err MATCHES "--set: debug\\.voxelSlice 2 is outside 0\\.\\.1; using 1")
  message(FATAL_ERROR "--set with an older key and a clamped value: exit ${rc}\n${err}")
endif()
expect_failure("--set out of range" 2 "--set: gi\\.voxelResolution is 100, expected a power of two"
  "${cornell}" --out "${OUT_DIR}/o.png" --set gi.voxelResolution=100)
expect_failure("--set unknown key" 2 "--set: unknown render setting 'gi\\.sparkles'"
  "${cornell}" --out "${OUT_DIR}/o.png" --set gi.sparkles=1)

# A sampler enum glTF does not allow used to end in GL errors and exit 0: now a warning and the
# default, and no GL error (any would make lit-render exit 1).
file(MAKE_DIRECTORY "${OUT_DIR}/sampler")
file(COPY "${SOURCE_DIR}/tests/fuzz/companions/tex.png" DESTINATION "${OUT_DIR}/sampler")
file(READ "${SOURCE_DIR}/tests/fuzz/seeds/textured_quad.gltf" quad_json)
string(REPLACE "\"wrapS\":33071" "\"wrapS\":12345" quad_json "${quad_json}")
file(WRITE "${OUT_DIR}/sampler/bad_sampler.gltf" "${quad_json}")
run_lit_render("${OUT_DIR}/sampler/bad_sampler.gltf" --out "${OUT_DIR}/sampler/quad.png" --size 16x16 --gi off)
if(NOT rc EQUAL 0 OR NOT err MATCHES "invalid wrapS 12345; using 10497" OR err MATCHES "error: GL")
  message(FATAL_ERROR "a bad sampler enum: exit ${rc}\n${err}")
endif()

foreach(file a b c d e f g h i j k l m n o p q)
  if(EXISTS "${OUT_DIR}/${file}.png")
    message(FATAL_ERROR "a failed run still wrote ${OUT_DIR}/${file}.png")
  endif()
endforeach()

# ---- Camera paths -----------------------------------------------------------------------------
# The Cornell box's path is a 12 s loop: at 2 fps that is 24 frames, frame_00000 ... frame_00023
# (a loop stops one frame short of its start). GI off keeps it quick.
set(path_file "${SOURCE_DIR}/assets/cornell_box.path.json")
set(frames_dir "${OUT_DIR}/path_frames")
run_lit_render("${cornell}" --path "${path_file}" --fps 2 --frames-out "${frames_dir}" --size 32x32 --gi off)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rendering the camera path failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
file(GLOB frames "${frames_dir}/frame_*.png")
list(LENGTH frames frame_count)
if(NOT frame_count EQUAL 24)
  message(FATAL_ERROR "expected 24 path frames in ${frames_dir}, found ${frame_count}\nstdout:\n${out}")
endif()
foreach(name frame_00000 frame_00023)
  if(NOT EXISTS "${frames_dir}/${name}.png")
    message(FATAL_ERROR "the path render did not write ${name}.png")
  endif()
endforeach()
# (The progress line appears only on renders long enough to need one.)
if(NOT out MATCHES "wrote 24 frames to")
  message(FATAL_ERROR "no summary line for the path render\nstdout:\n${out}\nstderr:\n${err}")
endif()
# Consecutive frames of a smooth path differ, but not all of them from the first.
file(MD5 "${frames_dir}/frame_00000.png" first_hash)
file(MD5 "${frames_dir}/frame_00001.png" second_hash)
if(first_hash STREQUAL second_hash)
  message(FATAL_ERROR "path frames 0 and 1 are identical: the camera did not move")
endif()

run_lit_render("${cornell}" --path "${path_file}" --fps 1 --bench-path --size 32x32 --gi off)
if(NOT rc EQUAL 0 OR NOT out MATCHES "lowest FPS [0-9.]+, highest FPS [0-9.]+, mean frame [0-9.]+ ms")
  message(FATAL_ERROR "--bench-path printed no statistics line (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()

expect_failure("missing path file" 2 "cannot use the camera path: .*no_such_path\\.json"
  "${cornell}" --path "${OUT_DIR}/no_such_path.json" --frames-out "${OUT_DIR}/never")
set(bad_path "${OUT_DIR}/bad_path.json")
file(WRITE "${bad_path}" "{\"version\": 1, \"keys\": [{\"time\": 1, \"position\": [0,0,0], \"rotation\": [0,0,0,1], \"yfov\": 0.8}, {\"time\": 0.5, \"position\": [1,0,0], \"rotation\": [0,0,0,1], \"yfov\": 0.8}]}\n")
expect_failure("path with times out of order" 2 "key 1"
  "${cornell}" --path "${bad_path}" --frames-out "${OUT_DIR}/never")
if(EXISTS "${OUT_DIR}/never")
  file(GLOB never_frames "${OUT_DIR}/never/*.png")
  if(never_frames)
    message(FATAL_ERROR "a rejected camera path still wrote frames: ${never_frames}")
  endif()
endif()

# Reference-only flags without --reference, and views the reference does not render.
expect_failure("spp without reference" 2 "--spp needs --reference"
  "${cornell}" --out "${OUT_DIR}/never.png" --spp 4)
expect_failure("reference albedo view" 2 "--reference renders the views final"
  "${cornell}" --reference --view albedo --out "${OUT_DIR}/never.png")

# ---- Scenes from Blender (tests/data/blender, tools/blender/make_scenes.py) ---------------------
# --path NAME plays a camera animation made in Blender: "fly" is 3 s long (frames 1..73 at
# 24 fps), so at 2 fps it is 7 frames (start and end included), and the camera moves.
set(blender_point "${SOURCE_DIR}/tests/data/blender/point.gltf")
set(fly_dir "${OUT_DIR}/fly_frames")
run_lit_render("${blender_point}" --path fly --fps 2 --frames-out "${fly_dir}" --size 32x32 --gi off)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--path fly failed (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
file(GLOB fly_frames "${fly_dir}/frame_*.png")
list(LENGTH fly_frames fly_count)
if(NOT fly_count EQUAL 7)
  message(FATAL_ERROR "expected 7 frames of Blender's 'fly' animation, found ${fly_count}\nstdout:\n${out}")
endif()
file(MD5 "${fly_dir}/frame_00000.png" fly_first)
file(MD5 "${fly_dir}/frame_00006.png" fly_last)
if(fly_first STREQUAL fly_last)
  message(FATAL_ERROR "the first and last frames of 'fly' are identical: the camera did not move")
endif()
expect_failure("unknown animation" 2 "no camera animation 'walk'.*'fly'"
  "${blender_point}" --path walk --frames-out "${OUT_DIR}/never_walk")

# Exposure in stops, auto exposure and the sky flags are accepted; auto exposure reports its value.
run_lit_render("${blender_point}" --out "${OUT_DIR}/auto.png" --size 32x32 --gi off --auto-exposure on --ev 0.5)
if(NOT rc EQUAL 0 OR NOT out MATCHES "auto exposure: [-+][0-9.]+ EV")
  message(FATAL_ERROR "--auto-exposure on printed no metered exposure (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()
# A sky image that cannot be read is reported and the gradient sky is used instead.
run_lit_render("${SOURCE_DIR}/assets/cornell_box.gltf" --out "${OUT_DIR}/sky.png" --size 32x32 --gi off
  --sky-hdr "${OUT_DIR}/no_such_sky.hdr")
if(NOT rc EQUAL 0 OR NOT err MATCHES "no_such_sky\\.hdr.*gradient")
  message(FATAL_ERROR "a missing sky image was not reported (exit ${rc})\nstdout:\n${out}\nstderr:\n${err}")
endif()

# --compare: the reference must be a Radiance .hdr of the render's size, checked before rendering.
configure_file("${ref_png}" "${OUT_DIR}/png_named.hdr" COPYONLY)
expect_failure("compare with a PNG" 2 "--compare: cannot read .*png_named\\.hdr: not a Radiance \\.hdr image"
  "${cornell}" --size 32x32 --compare "${OUT_DIR}/png_named.hdr")
expect_failure("compare size" 2 "reference\\.hdr is 32x32, the image will be 16x16: render both at one --size"
  "${cornell}" --size 16x16 --compare "${ref_hdr}")
