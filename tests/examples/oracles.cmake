# The cross-checks against OpenMesh's and CGAL's subdividers. Included by
# CMakeLists.txt (the "oracles" part).
# The peers (OpenMesh's and CGAL's subdividers) are compiled once for all
# oracle tests. They are optimised even in a debug or sanitizer build:
# they are reference code, and at -O0 they took most of those tests' time.
# The library also carries what every oracle test needs (its include
# folders and the interpreter, cache and source paths), so each test
# executable below only links it.
add_library(oracle_peers STATIC peers_openmesh.cpp peers_cgal.cpp)
target_link_libraries(oracle_peers PUBLIC vv::vvlib GTest::gtest PRIVATE OpenMeshTools CGAL::CGAL)
target_include_directories(oracle_peers PUBLIC ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/tests/interpreter
                           ${PROJECT_SOURCE_DIR}/tests/unit)
target_compile_definitions(oracle_peers PUBLIC
  VV_INTERPRETER="$<TARGET_FILE:vvinterpreter>" VV_TEST_CACHE="${example_cache}"
  VV_SOURCE_DIR="${PROJECT_SOURCE_DIR}" VV_ORACLE_MODELS="${CMAKE_CURRENT_BINARY_DIR}/oracle-models")
target_compile_options(oracle_peers PRIVATE $<$<CONFIG:Debug>:-O1>
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)  # OpenMesh's PropertyT::push_back trips GCC 12
vv_strict_warnings(oracle_peers)

file(GLOB oracle_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/oracle_*_test.cpp)
foreach(src IN LISTS oracle_tests)
  get_filename_component(name ${src} NAME_WE)
  add_executable(${name} ${src})
  target_link_libraries(${name} PRIVATE oracle_peers vv::formats GTest::gtest_main)
  add_dependencies(${name} vvinterpreter)
  vv_strict_warnings(${name})
  vv_use_test_pch(${name})
  # The cross-checks' models are compiled at -O0 (VV_OPT=0): the numbers
  # checked here do not depend on the build, and a model compiles in a
  # third of the CPU time of the default -O1 (the release build's tests,
  # runs included: 408 s of CPU against 230). The default level is built and run
  # by the tutorial's test and the benchmarks' smoke runs. Under the
  # sanitizers the models are compiled without them instead (a property
  # of gtest_discover_tests takes one value): the example cases run every
  # example as an instrumented model, and scripts/run-tests sets VV_OPT=0
  # for that build's tests.
  set(env ENVIRONMENT_MODIFICATION "VV_OPT=set:0")
  if(VV_SANITIZE)
    set(env ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1"
        ENVIRONMENT_MODIFICATION "VV_SANITIZE_MODELS=set:0")
  endif()
  # One test of an oracle executable at a time (they share exports); other
  # tests run beside them.
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES RESOURCE_LOCK ${name} TIMEOUT 600 ${env})
endforeach()
