# The radial canvas model of examples/ (issue 11): radial_cells run in
# batch mode; its summary, plots, the tissue it exports and reproducibility.
vv_interpreter_test(interpreter_bio_canvas_tests bio_canvas_test.cpp)
