#pragma once
// Translated vv programs as contenders: an example of examples/ translated
// by vvc and compiled as a model plugin at the interpreter's default flags
// (see CMakeLists.txt), run on the benchmark's input with only its steps
// timed.
#include "bench_result.hpp"

#include <string>

struct translated_model {
  std::string plugin;  // the model's shared object
  std::string input;   // the file its start block reads from ../models/, e.g. "pyramid.vvm"
};

// Each run is a fresh process (fork), so every run starts from the model's
// fresh globals and its heap is measured alone. `scratch` is a folder for
// the input file. Throws std::runtime_error with the model's error.
bench_result run_translated(const translated_model& model, const bench_input& input, int levels,
                            bool keep_positions, const std::string& scratch);
