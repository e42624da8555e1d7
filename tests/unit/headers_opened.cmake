# headers_opened(HEADER OUT): every header the preprocessor opens for
# `#include <HEADER>` with vvlib as a system include folder (-H lists them).
function(headers_opened header out)
  string(MAKE_C_IDENTIFIER ${header} name)
  headers_opened_by("#include <${header}>\n" ${name} opened)
  set(${out} "${opened}" PARENT_SCOPE)
endfunction()

# headers_opened_by(SOURCE NAME OUT): the same for a source text (NAME names
# its file in WORK).
function(headers_opened_by text name out)
  set(source ${WORK}/opened_${name}.cpp)
  file(WRITE ${source} "${text}")
  execute_process(COMMAND ${CXX} -std=c++17 -E -H -isystem ${VVLIB} ${source}
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE opened)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "cannot preprocess ${source}:\n${opened}")
  endif()
  set(${out} "${opened}" PARENT_SCOPE)
endfunction()
