# docs/tutorial.md section 11, its commands run as written in a copy of the
# checkout at a deep path, their outputs compared with what the tutorial
# shows. Included by CMakeLists.txt (the "tutorial" part): it checks the
# tutorial and the case machinery as a user meets them, in the plain build
# (the sanitizers do not change it).
add_test(NAME tutorial_regression_test_commands_work_as_written
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_tutorial.sh ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/tutorial-in-a-checkout-at-a-path-longer-than-forty-characters/src
                 $<TARGET_FILE:vvinterpreter> $<TARGET_FILE:vvm_check>
                 -- -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
                 -DVV_BUILD_BENCHMARKS=OFF)
set_tests_properties(tutorial_regression_test_commands_work_as_written PROPERTIES TIMEOUT 600)
