# Runs vvc on INPUT, which must fail with the diagnostic named in its first
# line (`// expect: LINE:COL: error: MESSAGE`, or for an error in a file it
# includes `// expect-in: PATH:LINE:COL: error: MESSAGE` with PATH relative
# to INPUT's folder), exit status 1, print the source line and a caret, and
# leave no OUTPUT (not even a stale one).
# With LINE_ENDS=CR or CRLF, a copy of INPUT with those line ends (beside
# OUTPUT) is translated instead: the diagnostic must be the same.
# Text is handled as strings, never as CMake lists (messages contain ';').
file(READ ${INPUT} source)
if(DEFINED LINE_ENDS)
  string(REPLACE "CR" "\r" ending "${LINE_ENDS}")
  string(REPLACE "LF" "\n" ending "${ending}")
  string(REPLACE "\n" "${ending}" source "${source}")
  get_filename_component(name ${INPUT} NAME)
  get_filename_component(dir ${OUTPUT} DIRECTORY)
  set(INPUT ${dir}/${LINE_ENDS}/${name})
  file(WRITE ${INPUT} "${source}")
endif()
string(REGEX MATCH "^// expect(-in)?: ([^\r\n]*)" first "${source}")
if(NOT first)
  message(FATAL_ERROR "${INPUT}: the first line must be '// expect: LINE:COL: error: MESSAGE'")
endif()
if(CMAKE_MATCH_1)
  get_filename_component(folder ${INPUT} DIRECTORY)
  set(expected "${folder}/${CMAKE_MATCH_2}")
else()
  set(expected "${INPUT}:${CMAKE_MATCH_2}")
endif()
get_filename_component(dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
file(WRITE ${OUTPUT} "stale output of an earlier run\n")
execute_process(COMMAND ${VVC} ${INPUT} -o ${OUTPUT}
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "vvc exited with ${status}, expected 1\n${err}")
endif()
string(REGEX MATCH "^[^\n]*" got "${err}")
if(NOT got STREQUAL expected)
  message(FATAL_ERROR "first diagnostic:\n  ${got}\nexpected:\n  ${expected}\nall output:\n${err}")
endif()
if(NOT err MATCHES "^[^\n]*\n  [^\n]*\n  [ \t]*\\^\n")
  message(FATAL_ERROR "the diagnostic lacks the source line and caret:\n${err}")
endif()
if(EXISTS ${OUTPUT})
  message(FATAL_ERROR "vvc left an output file behind on error")
endif()
message(STATUS "ok: ${got}")
