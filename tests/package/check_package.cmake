# `cmake --install` into a scratch prefix, then three outside projects, each
# finding the installed package `vv` and linking one target: the algebra
# alone, the formats, the OpenMesh bridge. Each must build, run and give the
# tetrahedron's counts, and load only the libraries of its own target.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed:\n${err}")
endif()

# project, arguments, libraries it must load, libraries it must not load
function(check_project name args needs refuses)
  set(work ${PREFIX}/projects/${name})
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/tests/package/${name} -B ${work}
                          -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
                          -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}
                          "-DCMAKE_CXX_FLAGS=${FLAGS}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: configuring against the installed package failed:\n${out}${err}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${work}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: the build failed:\n${out}${err}")
  endif()
  set(exe ${work}/use_${name})
  execute_process(COMMAND ${exe} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: the program failed:\n${out}${err}")
  endif()
  file(GET_RUNTIME_DEPENDENCIES EXECUTABLES ${exe} RESOLVED_DEPENDENCIES_VAR loaded
       UNRESOLVED_DEPENDENCIES_VAR missing)
  if(missing)
    message(FATAL_ERROR "${name}: libraries not found at run time: ${missing}")
  endif()
  foreach(lib IN LISTS needs)
    if(NOT loaded MATCHES "/lib${lib}[.]so")
      message(FATAL_ERROR "${name}: does not load lib${lib}:\n${loaded}")
    endif()
  endforeach()
  foreach(lib IN LISTS refuses)
    if(loaded MATCHES "/lib${lib}[.]so")
      message(FATAL_ERROR "${name}: loads lib${lib}, which its target does not need:\n${loaded}")
    endif()
  endforeach()
  if(name STREQUAL "formats" AND NOT loaded MATCHES "${PREFIX}/lib/libvv_formats[.]so")
    message(FATAL_ERROR "formats: vv_formats is not the installed one:\n${loaded}")
  endif()
  message(STATUS "${name}: ok\n${out}")
endfunction()

check_project(algebra "" "pugixml" "vv_formats;OpenMeshCore;GL;OpenGL;CGAL")
check_project(formats "${PREFIX}/tetrahedron.off" "vv_formats" "OpenMeshCore;GL;OpenGL")
check_project(openmesh "" "OpenMeshCore" "vv_formats;GL;OpenGL")
file(REMOVE_RECURSE ${PREFIX})
message(STATUS "ok")
