# VV_UNITY_BUILD=ON compiles each of the project's libraries and programs
# from a few combined sources (CMake's unity build): they share the parsing
# of their headers, which is most of their compile time, so a build from
# scratch takes about half the CPU (vv_formats 35 s -> 16 s, vvc_core
# 28 s -> 11 s). scripts/run-tests uses it; an incremental build is faster
# without it (an edit recompiles one file, not its group), hence OFF.
option(VV_UNITY_BUILD "Compile the project's libraries and programs as unity builds (faster from scratch)" OFF)

# Only our own targets: the test programs define helpers of the same names
# in different files, as separate files may.
function(vv_unity_build target)
  if(VV_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
  endif()
endfunction()

# Test programs of several files, likewise: their files' local helpers
# have names of their own, so that the files can be combined. Their
# fixtures live in unnamed namespaces, which GCC warns about once a file is
# included into another (-Wsubobject-linkage): harmless here, each unity
# source being one translation unit.
function(vv_unity_test_build target)
  if(VV_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-subobject-linkage>)
  endif()
endfunction()
