// The one source of the targets that only build a precompiled header for
// test programs to share: vv_test_pch (cmake/VVTestPrecompiledHeader.cmake)
// and vvp_pch (tests/vvc/CMakeLists.txt).
