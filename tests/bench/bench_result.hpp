#pragma once
// What one timed refinement reports, and the implementations that produce it.
#include "bench_input.hpp"

#include <array>
#include <cstddef>
#include <vector>

struct bench_result {
  double ms = 0;            // refinement only, mesh construction excluded
  double cpu_ms = 0;        // the same region in this thread's CPU time
  std::size_t bytes = 0;    // heap held by the refined mesh structure
  std::size_t vertices = 0, faces = 0;
  std::vector<std::array<double, 3>> positions;  // only if keep_positions
};

// Each refines `input` `levels` times. Triangle schemes read input.triangles,
// quad schemes input.quads.
using bench_runner = bench_result (*)(const bench_input& input, int levels, bool keep_positions);

bench_result run_vvlib_loop(const bench_input& input, int levels, bool keep_positions);

bench_result run_openmesh_loop(const bench_input& input, int levels, bool keep_positions);
bench_result run_openmesh_sqrt3(const bench_input& input, int levels, bool keep_positions);
bench_result run_openmesh_butterfly(const bench_input& input, int levels, bool keep_positions);
bench_result run_openmesh_catmull_clark(const bench_input& input, int levels, bool keep_positions);

bench_result run_cgal_loop(const bench_input& input, int levels, bool keep_positions);
bench_result run_cgal_sqrt3(const bench_input& input, int levels, bool keep_positions);
bench_result run_cgal_catmull_clark(const bench_input& input, int levels, bool keep_positions);
bench_result run_cgal_doo_sabin(const bench_input& input, int levels, bool keep_positions);

bench_result run_opensubdiv_loop(const bench_input& input, int levels, bool keep_positions);
bench_result run_opensubdiv_catmull_clark(const bench_input& input, int levels, bool keep_positions);
