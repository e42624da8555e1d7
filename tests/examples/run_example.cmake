# One example's regression test: run it in batch mode, export a mesh, and
# check the export with vvm_check (counts, golden file).
# -DINTERPRETER -DCHECK -DCACHE -DMODEL -DSTEPS -DOUT [-DSET] [-DMESH] [-DMAXFACE]
# [-DVERTICES -DEDGES -DFACES] -DGOLDEN [-DTOLERANCE] [-DOPT (--opt)]
# [-DUPDATE_GOLDEN=ON] [-DTHREADS (--threads)]
# With -DUPDATE_GOLDEN=ON (the cache option VV_UPDATE_GOLDEN, as
# docs/tutorial.md section 11 uses it) or VV_UPDATE_GOLDEN=1 in the
# environment (scripts/update-golden sets it for its own run only) the
# export is written to GOLDEN instead.
# What failed is printed as it is (message NOTICE), then a short error:
# CMake wraps the text of its errors at a width, so paths would move the
# line breaks of anything a test or a reader looks for.
set(args --batch --quiet --cache ${CACHE} --steps ${STEPS} --export ${OUT})
separate_arguments(parameters UNIX_COMMAND "${SET}")  # NAME=VALUE words
foreach(p IN LISTS parameters)
  list(APPEND args --set ${p})
endforeach()
if(MESH)
  list(APPEND args --mesh ${MESH})
endif()
if(NOT "${OPT}" STREQUAL "")
  list(APPEND args --opt ${OPT})
endif()
if(THREADS)
  list(APPEND args --threads ${THREADS})
endif()
execute_process(COMMAND ${INTERPRETER} ${args} ${MODEL} RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(NOTICE "${MODEL} failed:\n${err}")
  message(FATAL_ERROR "the model failed (see above)")
endif()
if(UPDATE_GOLDEN OR "$ENV{VV_UPDATE_GOLDEN}" STREQUAL "1")
  file(COPY_FILE ${OUT} ${GOLDEN})
  message(STATUS "updated ${GOLDEN}")
  return()
endif()
set(check ${OUT})
foreach(k VERTICES EDGES FACES)
  if(DEFINED ${k} AND NOT "${${k}}" STREQUAL "")
    string(TOLOWER ${k} opt)
    list(APPEND check --${opt} ${${k}})
  endif()
endforeach()
if(MAXFACE)
  list(APPEND check --max-face ${MAXFACE})
endif()
if(NOT EXISTS ${GOLDEN})
  message(NOTICE "no golden file ${GOLDEN} (scripts/update-golden writes it)")
  message(FATAL_ERROR "no golden file (see above)")
endif()
list(APPEND check --golden ${GOLDEN})
if(TOLERANCE)
  list(APPEND check --tolerance ${TOLERANCE})
endif()
execute_process(COMMAND ${CHECK} ${check} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(NOTICE "${out}${err}")
  message(FATAL_ERROR "the export does not pass the checks above")
endif()
message(STATUS "${out}")
