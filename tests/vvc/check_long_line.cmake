# An error in a very long source line (1 MB): the diagnostic shows at most
# 200 characters around the caret, marks each cut with "...", and the caret
# stays under the character the message names.
#
# -DVVC=vvc -DWORK=scratch folder
file(MAKE_DIRECTORY ${WORK})
set(input ${WORK}/long_line.vvp)
string(REPEAT "0+" 250000 half)  # 500,000 characters
file(WRITE ${input}
     "vertex { double c; };\n"
     "vertex after(vertex a, vertex v) {\n"
     "  int pad = ${half}0; vertex w = nextto a v; int more = ${half}0; (void)pad; (void)more; return w;\n"
     "}\n")
execute_process(COMMAND ${VVC} ${input} -o ${WORK}/long_line.cpp
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "vvc exited with ${status}, expected 1")
endif()
string(LENGTH "${err}" size)
if(size GREATER 1000)
  message(FATAL_ERROR "the diagnostic is ${size} bytes long")
endif()
# The column of the 'v' after `nextto a`: 2 spaces, "int pad = ", the
# half, "0; vertex w = nextto a ".
string(LENGTH "  int pad = ${half}0; vertex w = nextto a " before)
math(EXPR col "${before} + 1")
set(first "${input}:3:${col}: error: expected 'in' after the operand of 'nextto', found 'v'")
string(FIND "${err}" "\n" eol)
string(SUBSTRING "${err}" 0 ${eol} got)
if(NOT got STREQUAL first)
  message(FATAL_ERROR "first line:\n  ${got}\nexpected:\n  ${first}")
endif()
# The source line and the caret line, each after two spaces.
if(NOT err MATCHES "\n  (\\.\\.\\.[^\n]*\\.\\.\\.)\n  ( *\\^)\n$")
  message(FATAL_ERROR "no source line cut at both ends with a caret under it:\n${err}")
endif()
set(shown "${CMAKE_MATCH_1}")
set(caret "${CMAKE_MATCH_2}")
string(LENGTH "${shown}" width)
if(width GREATER 206)  # 200 characters and the two marks
  message(FATAL_ERROR "${width} characters of the line shown")
endif()
string(LENGTH "${caret}" at)
math(EXPR at "${at} - 1")
string(SUBSTRING "${shown}" ${at} 3 under)
if(NOT under STREQUAL "v; ")
  message(FATAL_ERROR "the caret is under '${under}', not under the 'v' of 'nextto a v;':\n${shown}\n${caret}")
endif()
message(STATUS "ok: ${size} bytes")
