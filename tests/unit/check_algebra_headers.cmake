# <vv/vv.hpp>, the algebra, needs GLM and pugixml only: the preprocessor
# (-H lists every header it opens) must open nothing of OpenMesh, CGAL or
# GL. The same check on the bridges that do use them must find them, so
# the test can fail.
include(${CMAKE_CURRENT_LIST_DIR}/headers_opened.cmake)

set(forbidden "/OpenMesh/" "/CGAL/" "/GL/")
headers_opened(vv/vv.hpp opened)
foreach(dir IN LISTS forbidden)
  string(REGEX MATCH "[^\n]*${dir}[^\n]*" found "${opened}")
  if(found)
    message(FATAL_ERROR "<vv/vv.hpp> includes a header of ${dir}:\n${found}")
  endif()
endforeach()

foreach(pair "vv/io/openmesh.hpp=/OpenMesh/" "algorithms/render.hpp=/GL/")
  string(REPLACE "=" ";" pair ${pair})
  list(GET pair 0 header)
  list(GET pair 1 dir)
  headers_opened(${header} opened)
  if(NOT opened MATCHES "${dir}")
    message(FATAL_ERROR "the check does not see ${dir} in <${header}>, which includes it")
  endif()
endforeach()
message(STATUS "ok")
