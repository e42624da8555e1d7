# A case file with a misspelt key is refused, naming its file and line: runs
# parse_case.cmake on CASE (bad_case.test.in, whose line 4 says `vertexes`)
# and checks the exit status and the one unwrapped error line. Matching
# CMake's own error text would depend on the path: CMake wraps it.
# -DPARSE_CASE -DCASE
execute_process(COMMAND ${CMAKE_COMMAND} -DCASE=${CASE} -P ${PARSE_CASE}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "the case file was accepted:\n${out}${err}")
endif()
set(expected "error: ${CASE}:4: unknown key 'vertexes' (known: model, steps, set, mesh, vertices, edges, faces, max_face, tolerance, view, gallery_mesh)")
string(FIND "${err}" "${expected}\n" at)
if(at LESS 0)
  message(FATAL_ERROR "no line\n  ${expected}\nin:\n${err}")
endif()
message(STATUS "ok")
