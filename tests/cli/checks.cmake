# Checks shared by the command-line tests (each runs as `cmake -P` and includes this file).

# run_program(EXE ARGS...): runs EXE with ARGS (5 min at most); sets rc, out and err (exit status,
# stdout, stderr) in the caller's scope.
macro(run_program exe)
  execute_process(COMMAND "${exe}" ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
endmacro()

# expect_written(FILE WHO DETAILS): FILE exists and is not empty; WHO names what should have
# written it, DETAILS (the tool's output) goes into the failure message.
function(expect_written file who details)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${who} did not write ${file}\n${details}")
  endif()
  file(SIZE "${file}" size)
  if(size EQUAL 0)
    message(FATAL_ERROR "${who} wrote an empty ${file}")
  endif()
endfunction()

# expect_png(FILE): FILE starts with the PNG signature.
function(expect_png file)
  file(READ "${file}" signature LIMIT 8 HEX)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${file} is not a PNG file (starts with ${signature})")
  endif()
endfunction()
