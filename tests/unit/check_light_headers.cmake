# The headers every model includes must not pull in CGAL (issue 9, item 4:
# it added about 4 s to the compile of every model that read a polygon
# file); the polygon formats come compiled, in vv_formats. The compiler's
# -H lists every header the preprocessor opens.
include(${CMAKE_CURRENT_LIST_DIR}/headers_opened.cmake)
foreach(header model/model.hpp vv/io/mesh_io.hpp vv/vv.hpp)
  headers_opened(${header} opened)
  string(REGEX MATCH "[^\n]*/CGAL/[^\n]*" cgal "${opened}")
  if(cgal)
    message(FATAL_ERROR "<${header}> includes CGAL:\n${cgal}")
  endif()
endforeach()
message(STATUS "ok")
