// The one source of vv_test_pch, the target that builds the test programs'
// shared precompiled header (cmake/VVTestPrecompiledHeader.cmake).
