# A sanitizer build of the interpreter instruments the models it compiles,
# and VV_SANITIZE_MODELS=0 leaves them uninstrumented (the host tests'
# setting). Checked on the compiled plugin: an instrumented one needs the
# AddressSanitizer runtime (__asan_init), a plain one does not.
# Both builds go to the tests' shared model cache: the instrumented one is
# the example cases' build of the same model, and the precompiled headers
# are the other tests' (a cache of its own built both headers again).
#   cmake -DINTERPRETER=... -DMODEL=... -DCACHE=... -P check_model_instrumentation.cmake
function(compiled_plugin setting out)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${setting}
                          ${INTERPRETER} --compile-only --cache ${CACHE} ${MODEL}
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "compile failed (${setting}):\n${output}${errors}")
  endif()
  # --compile-only prints the plugin's path as its last line.
  string(STRIP "${output}" output)
  string(REGEX REPLACE ".*\n" "" plugin "${output}")
  if(NOT EXISTS "${plugin}")
    message(FATAL_ERROR "--compile-only printed no plugin (${setting}):\n${output}${errors}")
  endif()
  file(REAL_PATH ${plugin} plugin)
  set(${out} ${plugin} PARENT_SCOPE)
endfunction()
function(needs_asan plugin out)
  execute_process(COMMAND nm -D --undefined-only ${plugin} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm failed on ${plugin}")
  endif()
  if(symbols MATCHES "__asan_init")
    set(${out} TRUE PARENT_SCOPE)
  else()
    set(${out} FALSE PARENT_SCOPE)
  endif()
endfunction()

compiled_plugin("VV_SANITIZE_MODELS=1" instrumented)
compiled_plugin("VV_SANITIZE_MODELS=0" plain)
if(plain STREQUAL instrumented)
  message(FATAL_ERROR "one build for both settings: ${plain}")
endif()
needs_asan(${instrumented} instrumented_needs)
needs_asan(${plain} plain_needs)
if(NOT instrumented_needs)
  message(FATAL_ERROR "the default model build is not instrumented: ${instrumented}")
endif()
if(plain_needs)
  message(FATAL_ERROR "VV_SANITIZE_MODELS=0 still instrumented the model: ${plain}")
endif()
message(STATUS "instrumented by default, plain with VV_SANITIZE_MODELS=0")
