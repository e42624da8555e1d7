# The tissue models of examples/ (issue 11): root_meristem, run in batch
# mode; its printed summary, exports and plots.
vv_interpreter_test(interpreter_bio_tissue_tests bio_tissue_test.cpp)
