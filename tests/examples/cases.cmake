# The example cases (cases/*.test) and the case machinery's own checks.
# Included by CMakeLists.txt (the "examples" part).
option(VV_UPDATE_GOLDEN "The example cases write their exports to tests/golden/ instead of comparing" OFF)

# Under the sanitizers the examples' models are instrumented and built at
# -O0, in about half the compile time (5.1 s against 9.1 s for loop.vvp).
# AddressSanitizer checks every memory access at -O0 too; the one UBSan
# check that needs optimisation (object-size) is covered by its bounds
# checks.
set(example_opt "")
if(VV_SANITIZE)
  set(example_opt 0)
endif()
include(${CMAKE_CURRENT_SOURCE_DIR}/parse_case.cmake)
file(GLOB cases CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/cases/*.test)
foreach(case IN LISTS cases)
  get_filename_component(name ${case} NAME_WE)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${case})  # edits re-read
  vv_parse_case(${case})
  file(READ ${PROJECT_SOURCE_DIR}/${model} source)
  set(threads "")
  if(source MATCHES "parallel forall")
    set(threads 2)
  endif()
  add_test(NAME example.${name}
           COMMAND ${CMAKE_COMMAND} -DINTERPRETER=$<TARGET_FILE:vvinterpreter> -DCHECK=$<TARGET_FILE:vvm_check>
                   -DCACHE=${example_cache} -DMODEL=${PROJECT_SOURCE_DIR}/${model} -DSTEPS=${steps} "-DSET=${set}"
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/${name}.vvm -DMESH=${mesh}
                   -DVERTICES=${vertices} -DEDGES=${edges} -DFACES=${faces} -DMAXFACE=${max_face}
                   -DTOLERANCE=${tolerance} -DGOLDEN=${PROJECT_SOURCE_DIR}/tests/golden/${name}.vvm
                   -DOPT=${example_opt} -DUPDATE_GOLDEN=${VV_UPDATE_GOLDEN} -DTHREADS=${threads}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/run_example.cmake)
  set_tests_properties(example.${name} PROPERTIES TIMEOUT 300 LABELS example)
  if(VV_SANITIZE)
    set_tests_properties(example.${name} PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
  endif()
  # An example with parallel forall runs its loops (and its mass-spring
  # steps, algorithms/physics.hpp) on 2 threads above, even where the mesh
  # is small (VV_PARALLEL_GRAIN=1), and exports the same bytes on one
  # thread: the same golden file. (An example whose only parallel loops are
  # mass-spring steps relaxes for thousands of steps of a few dozen
  # vertices: bench_springs and the unit tests check those on 2 threads.)
  if(source MATCHES "parallel forall")
    # Loops of a few dozen vertices on two threads wait at their ends far
    # more than they work: there the waiting thread sleeps at once
    # (OMP_WAIT_POLICY=passive) instead of spinning first, which had
    # doubled the CPU time of daffodil_corona's run (12.5 s against 6.9 s
    # for the same 6.4 to 7 s) and, on a busy machine, tripled its wall time.
    set(environment VV_PARALLEL_GRAIN=1 OMP_WAIT_POLICY=passive)
    if(VV_SANITIZE)
      list(APPEND environment ASAN_OPTIONS=detect_leaks=0:abort_on_error=1)
    endif()
    set_tests_properties(example.${name} PROPERTIES ENVIRONMENT "${environment}")
    add_test(NAME example.${name}.one_thread
             COMMAND ${CMAKE_COMMAND} -DINTERPRETER=$<TARGET_FILE:vvinterpreter> -DCHECK=$<TARGET_FILE:vvm_check>
                     -DCACHE=${example_cache} -DMODEL=${PROJECT_SOURCE_DIR}/${model} -DSTEPS=${steps} "-DSET=${set}"
                     -DOUT=${CMAKE_CURRENT_BINARY_DIR}/${name}.one_thread.vvm -DMESH=${mesh}
                     -DVERTICES=${vertices} -DEDGES=${edges} -DFACES=${faces} -DMAXFACE=${max_face}
                     -DTOLERANCE=${tolerance} -DGOLDEN=${PROJECT_SOURCE_DIR}/tests/golden/${name}.vvm
                     -DOPT=${example_opt} -DTHREADS=1
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/run_example.cmake)
    # After the 2-thread case: the model is then in the cache.
    set_tests_properties(example.${name}.one_thread PROPERTIES TIMEOUT 300 LABELS example DEPENDS example.${name})
    if(VV_SANITIZE)
      set_tests_properties(example.${name}.one_thread PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
    endif()
  endif()
endforeach()

# The checks of the case machinery itself, once from the source as it is
# and once through a path of more than 40 more characters: CMake wraps its
# error messages at a width, so a check of text that CMake has wrapped
# passes or fails with the length of the checkout's path. ROOT is the
# source as the tests reach it; WORK is where they write.
function(vv_add_case_checks suffix root work)
  file(MAKE_DIRECTORY ${work})
  # The runner compares (it never silently rewrites): a golden file that
  # differs makes the test fail, saying how.
  file(WRITE ${work}/wrong_golden.vvm "<mesh>\n  <v pos=\"0 0 0\" nb=\"\" />\n</mesh>\n")
  add_test(NAME example_runner_compares_with_the_golden_file${suffix}
           COMMAND ${CMAKE_COMMAND} -DINTERPRETER=$<TARGET_FILE:vvinterpreter> -DCHECK=$<TARGET_FILE:vvm_check>
                   -DCACHE=${example_cache} -DMODEL=${PROJECT_SOURCE_DIR}/examples/loop.vvp
                   -DOUT=${work}/runner_check.vvm -DGOLDEN=${work}/wrong_golden.vvm
                   -DRUNNER=${root}/tests/examples/run_example.cmake
                   -P ${root}/tests/examples/check_runner_refuses.cmake)
  set_tests_properties(example_runner_compares_with_the_golden_file${suffix} PROPERTIES TIMEOUT 300)
  # A case file with a misspelt key is refused, naming its line.
  add_test(NAME example_case_with_an_unknown_key_is_refused${suffix}
           COMMAND ${CMAKE_COMMAND} -DPARSE_CASE=${root}/tests/examples/parse_case.cmake
                   -DCASE=${root}/tests/examples/bad_case.test.in
                   -P ${root}/tests/examples/check_case_refused.cmake)
endfunction()
vv_add_case_checks("" ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR})
# The model is the same file in both (one compile): the paths that reach
# the messages are the case file's, the runner's and the export's.
set(deep ${CMAKE_CURRENT_BINARY_DIR}/a-checkout-at-a-path-longer-than-forty-characters)
file(MAKE_DIRECTORY ${deep})
file(CREATE_LINK ${PROJECT_SOURCE_DIR} ${deep}/src SYMBOLIC)
vv_add_case_checks("_from_a_deep_path" ${deep}/src ${deep}/build)
