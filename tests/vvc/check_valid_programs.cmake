# Every vv program of the repository that is meant to be valid (examples/,
# the tests' models and programs; not tests/vvc/errors/ and not the
# syntax_error.vvp models) translates with no diagnostic at all. Guards the
# guesses that name misspelt vv words ("did you mean ...?") against ever
# refusing a valid program.
#
# -DVVC=vvc -DSOURCE=the source tree
file(GLOB_RECURSE programs ${SOURCE}/examples/*.vvp ${SOURCE}/tests/*.vvp)
list(FILTER programs EXCLUDE REGEX "/tests/vvc/errors/|/syntax_error\\.vvp$")
list(LENGTH programs count)
if(count LESS 50)
  message(FATAL_ERROR "only ${count} programs found under ${SOURCE}")
endif()
foreach(vvp IN LISTS programs)
  execute_process(COMMAND ${VVC} ${vvp} -o - RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT err STREQUAL "")
    message(FATAL_ERROR "${vvp}: vvc exited with ${status}:\n${err}")
  endif()
endforeach()
message(STATUS "ok: ${count} programs")
