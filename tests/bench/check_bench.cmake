# A benchmark's smoke test: it must exit 0 AND print its result line
# (a regular expression alone would pass a run that failed after printing).
# -DCOMMAND="prog;arg;..." -DEXPECT=REGEX
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the benchmark exited with ${status}:\n${out}${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the benchmark did not print its result line (${EXPECT}):\n${out}${err}")
endif()
message(STATUS "ok")
