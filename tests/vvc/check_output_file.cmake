# Where `vvc -o FILE` writes, and what it never writes over: the program
# and the files it includes (however the path is spelt), devices and pipes
# (written through, never replaced, never removed), symbolic links (the
# link stays), and other runs' temporaries.
#
# -DVVC=vvc -DWORK=scratch folder -DPROGRAM=a valid .vvp
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/sub)
file(READ ${PROGRAM} program)
file(WRITE ${WORK}/a.vvp "${program}")
file(WRITE ${WORK}/inc.vvp "int included_value() { return 3; }\n")
file(WRITE ${WORK}/main.vvp "#include \"inc.vvp\"\nint twice() { return 2 * included_value(); }\n")
file(WRITE ${WORK}/bad.vvp "vertex after(vertex a, vertex v) { return nextto a v; }\n")

# run(STATUS PATTERN args...): vvc in WORK exits with STATUS and says PATTERN.
function(run expect_status pattern)
  execute_process(COMMAND ${VVC} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL ${expect_status})
    message(FATAL_ERROR "vvc ${ARGN}: exit ${status}, expected ${expect_status}\n${out}${err}")
  endif()
  if(NOT "${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "vvc ${ARGN}: messages do not match '${pattern}':\n${err}")
  endif()
endfunction()
function(unchanged file text)
  file(READ ${WORK}/${file} now)
  if(NOT now STREQUAL text)
    message(FATAL_ERROR "${file} was changed")
  endif()
endfunction()
# is(TEST file): `test TEST file` holds (-p FIFO, -c character device, -L link).
function(is test file)
  execute_process(COMMAND test ${test} ${file} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${file} is no longer what it was (test ${test} failed)")
  endif()
endfunction()
function(translated file)
  file(READ ${file} text)
  if(NOT text MATCHES "vv_plugin_descriptor")
    message(FATAL_ERROR "${file} does not hold the translation")
  endif()
endfunction()

# ---- the program and its includes, however spelt ----
set(over "refusing to write over the program: -o '[^']*' is the input file")
run(2 "${over}" a.vvp -o a.vvp)
run(2 "${over}" a.vvp -o ./a.vvp)
run(2 "${over}" ./a.vvp -o sub/../a.vvp)
run(2 "${over}" a.vvp -o ${WORK}/a.vvp)
file(CREATE_LINK a.vvp ${WORK}/link.vvp SYMBOLIC)
run(2 "${over}" a.vvp -o link.vvp)
is(-L ${WORK}/link.vvp)
file(CREATE_LINK ${WORK}/a.vvp ${WORK}/hard.vvp)
run(2 "${over}" a.vvp -o hard.vvp)
unchanged(a.vvp "${program}")
# A program with an error: the stale output removed after the error is not
# the program.
file(READ ${WORK}/bad.vvp bad)
run(2 "${over}" bad.vvp -o ./bad.vvp)
unchanged(bad.vvp "${bad}")
file(READ ${WORK}/inc.vvp inc)
run(2 "refusing to write over the program: -o 'inc.vvp' is '[^']*inc.vvp', which the program includes"
    main.vvp -o inc.vvp)
unchanged(inc.vvp "${inc}")
run(0 "^$" main.vvp -o main.cpp)
translated(${WORK}/main.cpp)

# ---- symbolic links: the file they name is written, the link stays ----
file(CREATE_LINK made.cpp ${WORK}/dangling.cpp SYMBOLIC)
run(0 "^$" a.vvp -o dangling.cpp)
is(-L ${WORK}/dangling.cpp)
translated(${WORK}/made.cpp)
file(CREATE_LINK loop2.cpp ${WORK}/loop1.cpp SYMBOLIC)
file(CREATE_LINK loop1.cpp ${WORK}/loop2.cpp SYMBOLIC)
run(1 "^loop1.cpp: error: cannot write file: the symbolic link is part of a loop of links\n$" a.vvp -o loop1.cpp)
is(-L ${WORK}/loop1.cpp)
is(-L ${WORK}/loop2.cpp)
# After an error, the stale file behind a link is removed, the link stays.
run(1 "bad.vvp:1:52: error" bad.vvp -o dangling.cpp)
is(-L ${WORK}/dangling.cpp)
if(EXISTS ${WORK}/made.cpp)
  message(FATAL_ERROR "the stale output behind the link was left after an error")
endif()
run(1 "^sub: error: cannot write file: it is a folder\n$" a.vvp -o sub)

# ---- unique temporaries ----
# The name a fixed temporary would have is taken by a folder: no matter.
file(MAKE_DIRECTORY ${WORK}/out.cpp.vvtmp.cpp)
run(0 "^$" a.vvp -o out.cpp)
translated(${WORK}/out.cpp)
# Six runs at once to one path: each succeeds, the result is whole, and no
# temporary is left.
set(runs "")
foreach(i RANGE 1 6)
  list(APPEND runs COMMAND ${VVC} a.vvp -o together.cpp)
endforeach()
execute_process(${runs} WORKING_DIRECTORY ${WORK} RESULTS_VARIABLE statuses ERROR_VARIABLE err)
if(NOT statuses STREQUAL "0;0;0;0;0;0")
  message(FATAL_ERROR "runs to one path failed (${statuses}):\n${err}")
endif()
run(0 "^$" a.vvp -o alone.cpp)
file(READ ${WORK}/alone.cpp alone)
unchanged(together.cpp "${alone}")
file(GLOB left ${WORK}/*vvtmp*)
list(REMOVE_ITEM left ${WORK}/out.cpp.vvtmp.cpp)
if(left)
  message(FATAL_ERROR "temporaries left behind: ${left}")
endif()
# A new file gets the usual mode (not the temporary's 0600); a file that
# exists keeps its own.
file(WRITE ${WORK}/plain.txt "")
execute_process(COMMAND stat -c %a ${WORK}/plain.txt ${WORK}/alone.cpp OUTPUT_VARIABLE modes)
string(REGEX MATCH "^([0-7]+)\n([0-7]+)\n$" ok "${modes}")
if(NOT ok OR NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2)
  message(FATAL_ERROR "a new output's mode differs from a new file's:\n${modes}")
endif()
execute_process(COMMAND chmod 640 ${WORK}/alone.cpp)
run(0 "^$" a.vvp -o alone.cpp)
execute_process(COMMAND stat -c %a ${WORK}/alone.cpp OUTPUT_VARIABLE mode)
if(NOT mode STREQUAL "640\n")
  message(FATAL_ERROR "the output's mode 640 became ${mode}")
endif()
# A name of 250 bytes (the longest a file name can be is 255): the
# temporary's suffix must not make it too long.
string(REPEAT "n" 246 long)
run(0 "^$" a.vvp -o ${long}.cpp)
translated(${WORK}/${long}.cpp)

# ---- pipes and devices: written through, never replaced or removed ----
execute_process(COMMAND mkfifo ${WORK}/pipe RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "mkfifo failed")
endif()
# vvc and a reader of the pipe run side by side (a pipeline's commands run
# at once; cat reads the FIFO, not vvc's standard output).
execute_process(COMMAND ${VVC} a.vvp -o pipe COMMAND cat pipe WORKING_DIRECTORY ${WORK}
                RESULTS_VARIABLE statuses OUTPUT_VARIABLE piped ERROR_VARIABLE err TIMEOUT 60)
if(NOT statuses STREQUAL "0;0" OR NOT piped MATCHES "vv_plugin_descriptor")
  message(FATAL_ERROR "writing to a FIFO failed (${statuses}):\n${err}")
endif()
is(-p ${WORK}/pipe)
# Devices of our own (mknod, as root): the machine's /dev is never at risk.
execute_process(COMMAND mknod ${WORK}/null c 1 3 RESULT_VARIABLE null_status ERROR_QUIET)
execute_process(COMMAND mknod ${WORK}/full c 1 7 RESULT_VARIABLE full_status ERROR_QUIET)
if(null_status EQUAL 0 AND full_status EQUAL 0)
  run(0 "^$" a.vvp -o null)
  is(-c ${WORK}/null)
  run(1 "^full: error: cannot write file: No space left on device\n$" a.vvp -o full)
  is(-c ${WORK}/full)
  run(1 "bad.vvp:1:52: error" bad.vvp -o null)
  is(-c ${WORK}/null)
  file(CREATE_LINK full ${WORK}/full_link SYMBOLIC)
  run(1 "^full_link: error: cannot write file: No space left on device\n$" a.vvp -o full_link)
  is(-c ${WORK}/full)
  is(-L ${WORK}/full_link)
else()
  message(STATUS "not root (mknod refused): the device cases were not run")
endif()
message(STATUS "ok")
