// bench_loop: times Loop subdivision in vvlib, OpenMesh and CGAL on the same
// closed triangle mesh, compares memory, and checks the results agree.
#include "bench_compare.hpp"
#include "bench_input.hpp"
#include "bench_result.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

const char* const usage =
    "usage: bench_loop [--input FILE] [--subdivisions S] [--levels K] [--runs R]\n"
    "  --input FILE       closed triangle mesh in any format OpenMesh reads\n"
    "                     (default: built-in icosphere)\n"
    "  --subdivisions S   icosphere level when no input is given (default 5:\n"
    "                     20480 triangles)\n"
    "  --levels K         Loop subdivision steps (default 3)\n"
    "  --runs R           timed runs per implementation; the median is kept\n"
    "                     (default 5)\n";

struct options {
  std::string input;
  int subdivisions = 5;
  int levels = 3;
  int runs = 5;
  bool help = false;
};

struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int parse_int(const std::string& name, const std::string& text, int lo, int hi)
{
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < lo || value > hi)
    throw usage_error(name + " needs an integer in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "], got '" + text + "'");
  return value;
}

options parse_options(int argc, char** argv)
{
  options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      opt.help = true;
      continue;
    }
    if (arg != "--input" && arg != "--subdivisions" && arg != "--levels" && arg != "--runs")
      throw usage_error("unknown option '" + arg + "' (see --help)");
    if (i + 1 >= argc) throw usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--input") opt.input = value;
    // Bounds keep the output mesh within memory: faces grow by 4 per level.
    else if (arg == "--subdivisions") opt.subdivisions = parse_int(arg, value, 0, 8);
    else if (arg == "--levels") opt.levels = parse_int(arg, value, 1, 8);
    else opt.runs = parse_int(arg, value, 1, 1000);
  }
  return opt;
}

using runner = bench_result (*)(const bench_input&, int, bool);

struct measured {
  const char* name;
  runner run;
  std::vector<double> ms;  // every run, in order
  bench_result first;      // bytes and positions come from the first run
  double median = 0;
  double bytes_per_vertex() const
  {
    return first.vertices ? static_cast<double>(first.bytes) / static_cast<double>(first.vertices) : 0.0;
  }
};

double median_of(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

void print_table(const std::vector<measured>& impls)
{
  std::printf("%-10s %11s %10s %10s %13s %9s  %s\n", "impl", "median ms", "V", "F", "bytes",
              "B/vertex", "runs (ms)");
  for (const measured& m : impls) {
    std::printf("%-10s %11.3f %10zu %10zu %13zu %9.1f  ", m.name, m.median, m.first.vertices,
                m.first.faces, m.first.bytes, m.bytes_per_vertex());
    for (std::size_t i = 0; i < m.ms.size(); ++i) std::printf(i ? " %.3f" : "%.3f", m.ms[i]);
    std::printf("\n");
  }
}

int run(const options& opt)
{
  const bench_input input = opt.input.empty() ? make_icosphere(opt.subdivisions) : read_input(opt.input);
  const std::string source =
      opt.input.empty() ? "icosphere(" + std::to_string(opt.subdivisions) + ")" : opt.input;
  std::printf("input: %s, %zu vertices, %zu triangles; %d Loop levels, %d runs each\n\n",
              source.c_str(), input.points.size(), input.triangles.size(), opt.levels, opt.runs);

  std::vector<measured> impls = {{"vvlib", run_vvlib_loop, {}, {}, 0},
                                 {"openmesh", run_openmesh_loop, {}, {}, 0},
                                 {"cgal", run_cgal_loop, {}, {}, 0}};
  // One-time allocations inside the libraries (statics, lazy singletons)
  // would otherwise be charged to whichever implementation runs first.
  const bench_input warm_up = make_icosphere(0);
  for (measured& m : impls) m.run(warm_up, 1, false);

  // Runs are interleaved so that drift (clock speed, heat) hits all alike.
  for (int r = 0; r < opt.runs; ++r)
    for (measured& m : impls) {
      bench_result result = m.run(input, opt.levels, r == 0);
      m.ms.push_back(result.ms);
      if (r == 0) m.first = std::move(result);
    }
  for (measured& m : impls) m.median = median_of(m.ms);
  const measured &vv = impls[0], &om = impls[1], &cg = impls[2];

  print_table(impls);
  const double vs_openmesh = vv.median / om.median, vs_cgal = vv.median / cg.median;
  std::printf("\ntime vvlib/OpenMesh: %.3f\ntime vvlib/CGAL:     %.3f\n", vs_openmesh, vs_cgal);

  const double tolerance = 1e-9 * mesh_size(input);
  std::string problem;
  for (const measured* other : {&vv, &cg}) {
    const std::string why = compare_results(other->first, om.first, tolerance);
    if (!why.empty()) problem += (problem.empty() ? "" : "; ") + std::string(other->name) + " vs openmesh: " + why;
  }
  if (problem.empty()) std::printf("agree: yes\n");
  else std::printf("agree: NO (%s)\n", problem.c_str());

  std::printf("loop%d vvlib_ms=%.3f openmesh_ms=%.3f cgal_ms=%.3f vs_openmesh=%.3f vs_cgal=%.3f "
              "vvlib_bytes_per_vertex=%.1f cgal_bytes_per_vertex=%.1f openmesh_bytes_per_vertex=%.1f\n",
              opt.levels, vv.median, om.median, cg.median, vs_openmesh, vs_cgal, vv.bytes_per_vertex(),
              cg.bytes_per_vertex(), om.bytes_per_vertex());
  return problem.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv)
{
  try {
    const options opt = parse_options(argc, argv);
    if (opt.help) {
      std::fputs(usage, stdout);
      return 0;
    }
    return run(opt);
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "bench_loop: error: %s\n", e.what());
    return 2;
  }
}
