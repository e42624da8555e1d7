# The cell division models of examples/ (issue 11): cells per generation,
# the tissue's invariants and reproducible exports.
vv_interpreter_test(interpreter_bio_physics_tests bio_physics_test.cpp)
