# <vv/vv.hpp>, the algebra, needs GLM and pugixml only: the preprocessor
# (-H lists every header it opens) must open nothing of OpenMesh, CGAL or
# GL, and nothing of the model layer (vvlib/model/: the plugin ABI, the
# proxy, the file objects; it was vv/plugin/ once). No header under vv/
# opens GL or any vvlib header outside vv/. The same check on the headers that do use them must find
# them, so the test can fail.
include(${CMAKE_CURRENT_LIST_DIR}/headers_opened.cmake)

set(forbidden "/OpenMesh/" "/CGAL/" "/GL/" "${VVLIB}/model/" "${VVLIB}/vv/plugin/")
headers_opened(vv/vv.hpp opened)
foreach(dir IN LISTS forbidden)
  string(REGEX MATCH "[^\n]*${dir}[^\n]*" found "${opened}")
  if(found)
    message(FATAL_ERROR "<vv/vv.hpp> includes a header of ${dir}:\n${found}")
  endif()
endforeach()

# Every header under vv/ at once (vv/io/openmesh.hpp may open OpenMesh).
file(GLOB_RECURSE algebra RELATIVE ${VVLIB} ${VVLIB}/vv/*.hpp)
set(all_of_them "")
foreach(header IN LISTS algebra)
  string(APPEND all_of_them "#include <${header}>\n")
endforeach()
headers_opened_by("${all_of_them}" every_vv_header opened)
string(REGEX MATCH "[^\n]*/GL/[^\n]*" found "${opened}")
if(found)
  message(FATAL_ERROR "a header under vv/ includes GL:\n${found}")
endif()
string(REPLACE "\n" ";" lines "${opened}")
foreach(opened_line IN LISTS lines)
  if(opened_line MATCHES "${VVLIB}/" AND (NOT opened_line MATCHES "${VVLIB}/vv/" OR opened_line MATCHES "${VVLIB}/vv/plugin/"))
    message(FATAL_ERROR "a header under vv/ includes one of vvlib outside the algebra:\n${opened_line}")
  endif()
endforeach()

foreach(pair "vv/io/openmesh.hpp=/OpenMesh/" "algorithms/render.hpp=/GL/" "util/palette.hpp=${VVLIB}/model/")
  string(REPLACE "=" ";" pair ${pair})
  list(GET pair 0 header)
  list(GET pair 1 dir)
  headers_opened(${header} opened)
  if(NOT opened MATCHES "${dir}")
    message(FATAL_ERROR "the check does not see ${dir} in <${header}>, which includes it")
  endif()
endforeach()
message(STATUS "ok")
