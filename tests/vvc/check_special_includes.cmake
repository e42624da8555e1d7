# vvc refuses an #include of what is no regular file, or of a file over the
# limit of program files, before the compiler reads it: g++ would read
# `#include "/dev/zero"` without end and wait on a FIFO for ever. .vvp files
# are read by vvc itself; other headers are checked where the compiler
# would first look (beside the including file, or at an absolute path).
# -DVVC -DWORK
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(name pipe.vvp pipe.h)
  execute_process(COMMAND mkfifo ${WORK}/${name} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "mkfifo ${WORK}/${name} failed")
  endif()
endforeach()
file(CREATE_LINK /dev/zero ${WORK}/zero.vvp SYMBOLIC)
file(CREATE_LINK /dev/zero ${WORK}/zero.h SYMBOLIC)
file(MAKE_DIRECTORY ${WORK}/folder.h)
# 64 MiB and one byte, sparse: no time, no disk.
foreach(name huge.vvp huge.h)
  execute_process(COMMAND truncate -s 67108865 ${WORK}/${name} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "truncate ${WORK}/${name} failed")
  endif()
endforeach()
file(WRITE ${WORK}/fine.h "inline int fine() { return 1; }\n")

# A program that includes `spelled` on its line 2 must fail with `message`
# there; a vvc that waits on a FIFO is stopped after 20 s.
function(expect_refused spelled message)
  file(WRITE ${WORK}/m.vvp "// includes ${spelled}\n#include ${spelled}\nstart {}\n")
  execute_process(COMMAND ${VVC} ${WORK}/m.vvp -o ${WORK}/m.cpp TIMEOUT 20
                  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT status EQUAL 1)
    message(FATAL_ERROR "#include ${spelled}: vvc ended with '${status}', expected 1\n${err}")
  endif()
  string(REGEX MATCH "^[^\n]*" first "${err}")
  if(NOT first STREQUAL "${WORK}/m.vvp:2:1: error: ${message}")
    message(FATAL_ERROR "#include ${spelled}:\n  ${first}\nexpected:\n  ${WORK}/m.vvp:2:1: error: ${message}")
  endif()
endfunction()

set(fifo "it is a FIFO (named pipe), not a regular file")
set(zero "it is a symbolic link to /dev/zero, a character device, not a regular file")
set(huge "it is 64 MiB (67108865 bytes), over the 64 MiB limit of program files")
expect_refused("\"pipe.vvp\"" "cannot open included file 'pipe.vvp': ${fifo}")
expect_refused("\"zero.vvp\"" "cannot open included file 'zero.vvp': ${zero}")
expect_refused("\"huge.vvp\"" "cannot open included file 'huge.vvp': ${huge}")
expect_refused("\"/dev/zero\"" "cannot include \"/dev/zero\": it is a character device, not a regular file")
expect_refused("</dev/zero>" "cannot include </dev/zero>: it is a character device, not a regular file")
expect_refused("\"pipe.h\"" "cannot include \"pipe.h\": ${fifo}")
expect_refused("\"zero.h\"" "cannot include \"zero.h\": ${zero}")
expect_refused("\"folder.h\"" "cannot include \"folder.h\": it is a folder, not a file")
expect_refused("\"huge.h\"" "cannot include \"huge.h\": ${huge}")

# Regular headers, and names the compiler finds elsewhere, pass.
file(WRITE ${WORK}/m.vvp "#include \"fine.h\"\n#include <vector>\n#include \"util/point.hpp\"\nstart {}\n")
execute_process(COMMAND ${VVC} ${WORK}/m.vvp -o ${WORK}/m.cpp TIMEOUT 20 RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "regular includes were refused:\n${err}")
endif()
message(STATUS "ok")
