# vv_parse_case(FILE): reads one regression case (cases/NAME.test) into the
# caller's variables model, steps, set, mesh, vertices, edges, faces,
# max_face, tolerance, view and gallery_mesh (the last two only for the
# picture of scripts/make-gallery, which draws the example as it is; `set`:
# parameters of the regression run, NAME=VALUE words given as --set). Lines are `key = value` (a `#` that starts a word
# starts a comment); a key that is not one of those, or a line that is not
# a `key = value`, is an error naming the file and line: a typo must not
# drop a check without a word. Run as a script, it prints the error as one
# unwrapped line, "error: FILE:LINE: ...", before failing: CMake wraps its
# own error messages at a width, so a longer path moves the line breaks.
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST), also when run as a script
set(VV_CASE_KEYS model steps set mesh vertices edges faces max_face tolerance view gallery_mesh)

# Stops at a case file's error: in a configure, as CMake's error; as a
# script, first as one line that tests can match whatever the path.
function(vv_case_error text)
  if(CMAKE_SCRIPT_MODE_FILE)
    message(NOTICE "error: ${text}")
    message(FATAL_ERROR "the case file is refused (see the line above)")
  endif()
  message(FATAL_ERROR "${text}")
endfunction()

function(vv_parse_case file)
  foreach(key IN LISTS VV_CASE_KEYS)
    set(${key} "")
  endforeach()
  file(STRINGS ${file} lines)
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    string(REGEX REPLACE "(^|[ \t])#.*$" "" line "${line}")
    if(line MATCHES "^[ \t]*$")
      continue()
    endif()
    if(NOT line MATCHES "^[ \t]*([A-Za-z_]+)[ \t]*=[ \t]*(.*[^ \t])[ \t]*$")
      vv_case_error("${file}:${n}: expected 'key = value', found '${line}'")
    endif()
    set(key ${CMAKE_MATCH_1})
    set(value "${CMAKE_MATCH_2}")
    if(NOT key IN_LIST VV_CASE_KEYS)
      string(REPLACE ";" ", " known "${VV_CASE_KEYS}")
      vv_case_error("${file}:${n}: unknown key '${key}' (known: ${known})")
    endif()
    set(${key} "${value}")
  endforeach()
  if(NOT model OR steps STREQUAL "")
    vv_case_error("${file}: needs 'model =' and 'steps ='")
  endif()
  foreach(key IN LISTS VV_CASE_KEYS)
    set(${key} "${${key}}" PARENT_SCOPE)
  endforeach()
endfunction()

# As a script (cmake -DCASE=FILE -P parse_case.cmake): check one case file.
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE AND DEFINED CASE)
  vv_parse_case(${CASE})
  message(STATUS "ok: ${CASE}")
endif()
