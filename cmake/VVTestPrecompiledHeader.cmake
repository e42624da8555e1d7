# One precompiled header for the test programs: GoogleTest, the vv algebra
# and the standard headers most test files open. It is built once, by
# vv_test_pch, and every test executable reuses it (vv_use_test_pch), so
# those headers are parsed once per build instead of once per test file.
# It is built with the test programs' options, strict warnings included
# (-Wpedantic changes what GCC predefines); GCC checks that they match and,
# with -Winvalid-pch (an error under -Werror), says so if a file cannot use
# it.
add_library(vv_test_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/test_pch_anchor.cpp)
target_link_libraries(vv_test_pch PRIVATE vv::vvlib GTest::gtest)
vv_strict_warnings(vv_test_pch)
target_precompile_headers(vv_test_pch PRIVATE
  <algorithm> <array> <cmath> <filesystem> <fstream> <functional> <map> <regex> <set>
  <sstream> <string> <vector>
  <gtest/gtest.h>
  <util/point.hpp> <vv/vv.hpp> <vv/io/from_faces.hpp> <vv/io/mesh_io.hpp>)

function(vv_use_test_pch target)
  target_precompile_headers(${target} REUSE_FROM vv_test_pch)
  # The header was built with vvlib's options, OpenMP's (-fopenmp) among
  # them: a test that does not use vvlib needs them too to use it.
  target_link_libraries(${target} PRIVATE vv::vvlib)
endfunction()
