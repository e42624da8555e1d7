# The headers every model includes must not pull in CGAL (issue 9, item 4:
# it added about 4 s to the compile of every model that read a polygon
# file); the polygon formats come compiled, in vv_formats. The compiler's
# -H lists every header the preprocessor opens.
foreach(header vv/plugin/model.hpp vv/io/mesh_io.hpp vv/vv.hpp)
  string(MAKE_C_IDENTIFIER ${header} name)
  set(source ${WORK}/light_${name}.cpp)
  file(WRITE ${source} "#include <${header}>\n")
  execute_process(COMMAND ${CXX} -std=c++17 -E -H -isystem ${VVLIB} ${source}
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE opened)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "cannot preprocess <${header}>:\n${opened}")
  endif()
  string(REGEX MATCH "[^\n]*/CGAL/[^\n]*" cgal "${opened}")
  if(cgal)
    message(FATAL_ERROR "<${header}> includes CGAL:\n${cgal}")
  endif()
endforeach()
message(STATUS "ok")
