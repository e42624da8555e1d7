# The example runner compares (it never silently rewrites): an export that
# differs from the golden file makes it fail, saying how. Runs
# run_example.cmake with a golden file of one vertex for loop.vvp after one
# step (18 vertices) and checks the exit status and vvm_check's line,
# printed unwrapped whatever the paths.
# -DRUNNER and run_example.cmake's arguments
execute_process(COMMAND ${CMAKE_COMMAND} -DINTERPRETER=${INTERPRETER} -DCHECK=${CHECK} -DCACHE=${CACHE}
                        -DMODEL=${MODEL} -DSTEPS=1 -DOUT=${OUT} -DGOLDEN=${GOLDEN} -P ${RUNNER}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "the runner passed an export that differs from the golden file:\n${out}${err}")
endif()
set(expected "differs from ${GOLDEN}: 18 elements, expected 1")
string(FIND "${err}" "${expected}\n" at)
if(at LESS 0)
  message(FATAL_ERROR "no line\n  ${expected}\nin:\n${err}")
endif()
message(STATUS "ok")
