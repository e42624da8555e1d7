# `cmake --install` into a scratch prefix, then the installed interpreter
# builds and runs a model against the installed headers.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed:\n${err}")
endif()
foreach(f bin/vvinterpreter bin/vvc lib/libvv_formats.so include/vv-1/model/model.hpp include/vv-1/util/point.hpp
          include/vv-1/algorithms/insert.hpp)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
execute_process(COMMAND ${PREFIX}/bin/vvinterpreter --batch --steps 2 --quiet --cache ${PREFIX}/cache
                        --export ${PREFIX}/out.vvm ${MODEL}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed interpreter failed:\n${out}${err}")
endif()
file(STRINGS ${PREFIX}/out.vvm vertices REGEX "<v ")
list(LENGTH vertices n)
if(NOT n EQUAL 66)
  message(FATAL_ERROR "expected 66 vertices after 2 Loop steps, found ${n}")
endif()
# The model was compiled against the installed headers, not the source tree.
# (Each build has a folder of its own; the cache key is a link to it.)
file(GLOB built ${PREFIX}/cache/plugins/*.*/command)
list(LENGTH built builds)
if(NOT builds EQUAL 1)
  message(FATAL_ERROR "expected one build in the cache, found: ${built}")
endif()
file(READ "${built}" command)
if(NOT command MATCHES "-isystem ${PREFIX}/include/vv-1 " OR command MATCHES "${SOURCE}/vvlib")
  message(FATAL_ERROR "the model was not compiled against the installed headers:\n${command}")
endif()
# ... and linked against the installed formats library.
if(NOT command MATCHES "-L ${PREFIX}/lib -Wl,-rpath,${PREFIX}/lib -lvv_formats")
  message(FATAL_ERROR "the model was not linked against the installed vv_formats:\n${command}")
endif()
file(REMOVE_RECURSE ${PREFIX})
message(STATUS "ok")
