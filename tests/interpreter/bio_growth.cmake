# The growth models of examples/ (issue 11): lsystem_koch, phyllotaxis and
# sea_shell, run in batch mode; their printed summaries, exports and plots.
vv_interpreter_test(interpreter_bio_growth_tests bio_growth_test.cpp)
