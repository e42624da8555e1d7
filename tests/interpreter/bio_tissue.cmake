# The tissue models of examples/ (issue 11): root_meristem and
# daffodil_corona, run in batch mode; their printed summaries, exports and
# plots.
vv_interpreter_test(interpreter_bio_tissue_tests bio_tissue_test.cpp)
