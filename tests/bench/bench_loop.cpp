// bench_loop: times subdivision schemes in vv and in the mesh libraries on
// the same closed meshes, in one process: the translated thesis programs
// (examples/*.vvp), Loop written directly against vvlib, OpenMesh, CGAL and
// OpenSubdiv. Prints medians, ratios of vv against each peer measured in
// the same run, heap bytes per vertex, and whether the results agree.
#include "bench_compare.hpp"
#include "bench_input.hpp"
#include "bench_result.hpp"
#include "bench_translated.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

const char* const usage =
    "usage: bench_loop [--input FILE] [--subdivisions S] [--torus N] [--levels K] [--runs R]\n"
    "                  [--schemes NAME,...]\n"
    "  --input FILE       closed triangle mesh in any format OpenMesh reads, for the\n"
    "                     triangle schemes (default: built-in icosphere)\n"
    "  --subdivisions S   icosphere level when no input is given (default 5:\n"
    "                     20480 triangles)\n"
    "  --torus N          the quad schemes' input: a torus of N x N quads (default\n"
    "                     100: 10000 quads)\n"
    "  --levels K         subdivision steps of every scheme (default: 3, and 4 for\n"
    "                     sqrt3)\n"
    "  --runs R           timed runs per implementation; the median is kept\n"
    "                     (default 5)\n"
    "  --schemes LIST     some of loop,catmull_clark,sqrt3,doo_sabin,butterfly\n"
    "                     (default: all)\n";

const char* const all_schemes[] = {"loop", "catmull_clark", "sqrt3", "doo_sabin", "butterfly"};

struct options {
  std::string input;
  int subdivisions = 5;
  int torus = 100;
  int levels = 0;  // 0: each scheme's default
  int runs = 5;
  std::vector<std::string> schemes{std::begin(all_schemes), std::end(all_schemes)};
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

std::vector<std::string> parse_schemes(const std::string& text)
{
  std::vector<std::string> names;
  std::stringstream list(text);
  for (std::string name; std::getline(list, name, ',');) {
    if (std::find(std::begin(all_schemes), std::end(all_schemes), name) == std::end(all_schemes))
      throw usage_error("unknown scheme '" + name + "' (see --help)");
    names.push_back(name);
  }
  if (names.empty()) throw usage_error("--schemes needs at least one scheme");
  return names;
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
    if (arg != "--input" && arg != "--subdivisions" && arg != "--torus" && arg != "--levels" &&
        arg != "--runs" && arg != "--schemes")
      throw usage_error("unknown option '" + arg + "' (see --help)");
    if (i + 1 >= argc) throw usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--input") opt.input = value;
    // Bounds keep the output meshes within memory.
    else if (arg == "--subdivisions") opt.subdivisions = parse_int(arg, value, 0, 7);
    else if (arg == "--torus") opt.torus = parse_int(arg, value, 3, 400);
    else if (arg == "--levels") opt.levels = parse_int(arg, value, 1, 6);
    else if (arg == "--schemes") opt.schemes = parse_schemes(value);
    else opt.runs = parse_int(arg, value, 1, 1000);
  }
  return opt;
}

using run_fn = std::function<bench_result(const bench_input&, int, bool)>;

struct contender {
  contender(std::string name_, run_fn run_, bool same_positions_)
      : name(std::move(name_)), run(std::move(run_)), same_positions(same_positions_) {}
  std::string name;
  run_fn run;
  bool same_positions;  // its positions must match the reference's, not only its counts
  std::vector<double> ms, cpu_ms;  // every run, in order
  bench_result first;              // bytes and positions come from the first run
  double median = 0, cpu_median = 0;
  double bytes_per_vertex() const
  {
    return first.vertices ? static_cast<double>(first.bytes) / static_cast<double>(first.vertices) : 0.0;
  }
};

// One scheme: its input, its levels and who runs it. contenders[0] is the
// reference the others are checked against.
struct scheme_run {
  std::string name;
  const bench_input* input;
  int levels;
  std::vector<contender> contenders;
};

double median_of(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

void print_table(const scheme_run& s)
{
  std::printf("%-10s %11s %9s %9s %9s %12s %9s  %s\n", "impl", "median ms", "cpu ms", "V", "F", "bytes",
              "B/vertex", "runs (ms)");
  for (const contender& c : s.contenders) {
    std::printf("%-10s %11.3f %9.3f %9zu %9zu %12zu %9.1f  ", c.name.c_str(), c.median, c.cpu_median,
                c.first.vertices, c.first.faces, c.first.bytes, c.bytes_per_vertex());
    for (std::size_t i = 0; i < c.ms.size(); ++i) std::printf(i ? " %.3f" : "%.3f", c.ms[i]);
    std::printf("\n");
  }
}

// What differs from the reference (empty: all agree).
std::string disagreements(const scheme_run& s)
{
  const contender& ref = s.contenders[0];
  const double tolerance = 1e-9 * mesh_size(*s.input);
  std::string problem;
  for (std::size_t i = 1; i < s.contenders.size(); ++i) {
    const contender& c = s.contenders[i];
    std::string why;
    if (c.same_positions) why = compare_results(c.first, ref.first, tolerance);
    else if (c.first.vertices != ref.first.vertices || c.first.faces != ref.first.faces)
      why = "counts V " + std::to_string(c.first.vertices) + " F " + std::to_string(c.first.faces) + " vs V " +
            std::to_string(ref.first.vertices) + " F " + std::to_string(ref.first.faces);
    if (!why.empty()) problem += (problem.empty() ? "" : "; ") + c.name + " vs " + ref.name + ": " + why;
  }
  return problem;
}

// Runs one scheme, prints its table, ratios and machine-readable line;
// false when the results disagree.
bool run_scheme(scheme_run& s, int runs, const bench_input& warm_up)
{
  const bench_input& input = *s.input;
  std::printf("== %s: %zu vertices, %zu faces, %d levels, %d runs each\n", s.name.c_str(), input.points.size(),
              input.triangles.size() + input.quads.size(), s.levels, runs);
  // One-time allocations inside the libraries (statics, lazy singletons)
  // would otherwise be charged to whichever implementation runs first.
  for (contender& c : s.contenders) c.run(warm_up, 1, false);
  // Runs are interleaved so that drift (clock speed, heat, other load) hits all alike.
  for (int r = 0; r < runs; ++r)
    for (contender& c : s.contenders) {
      bench_result result = c.run(input, s.levels, r == 0);
      c.ms.push_back(result.ms);
      c.cpu_ms.push_back(result.cpu_ms);
      if (r == 0) c.first = std::move(result);
    }
  for (contender& c : s.contenders) {
    c.median = median_of(c.ms);
    c.cpu_median = median_of(c.cpu_ms);
  }
  print_table(s);

  std::string line = s.name + std::to_string(s.levels);
  for (const contender& c : s.contenders) {
    char field[96];
    std::snprintf(field, sizeof field, " %s_ms=%.3f", c.name.c_str(), c.median);
    line += field;
  }
  std::printf("\n");
  for (const contender& ours : s.contenders) {
    if (ours.name != "vv" && ours.name != "vvlib") continue;
    for (const contender& peer : s.contenders) {
      if (peer.name == "vv" || peer.name == "vvlib") continue;
      const double ratio = ours.median / peer.median, cpu_ratio = ours.cpu_median / peer.cpu_median;
      std::printf("time %s/%s: %.3f (cpu time: %.3f)\n", ours.name.c_str(), peer.name.c_str(), ratio, cpu_ratio);
      char field[128];
      std::snprintf(field, sizeof field, " %s_vs_%s=%.3f %s_vs_%s_cpu=%.3f", ours.name.c_str(), peer.name.c_str(),
                    ratio, ours.name.c_str(), peer.name.c_str(), cpu_ratio);
      line += field;
    }
  }
  for (const contender& c : s.contenders) {
    char field[96];
    std::snprintf(field, sizeof field, " %s_bytes_per_vertex=%.1f", c.name.c_str(), c.bytes_per_vertex());
    line += field;
  }
  const std::string problem = disagreements(s);
  if (problem.empty()) std::printf("agree: yes\n");
  else std::printf("agree: NO (%s)\n", problem.c_str());
  std::printf("%s\n\n", line.c_str());
  return problem.empty();
}

// A folder of our own for the translated models' input files.
struct scratch_dir {
  std::string path;
  scratch_dir()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "vv_bench_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder in " + pattern);
    path = pattern;
  }
  ~scratch_dir()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  scratch_dir(const scratch_dir&) = delete;
  scratch_dir& operator=(const scratch_dir&) = delete;
};

run_fn translated(const std::string& example, const std::string& input_file, const std::string& scratch)
{
  const translated_model model{std::string(VV_BENCH_MODELS) + "/" + example + ".so", input_file};
  return [model, scratch](const bench_input& input, int levels, bool keep) {
    return run_translated(model, input, levels, keep, scratch);
  };
}

int run(const options& opt)
{
  const bench_input triangles = opt.input.empty() ? make_icosphere(opt.subdivisions) : read_input(opt.input);
  const bench_input quads = make_quad_torus(opt.torus);
  const std::string source =
      opt.input.empty() ? "icosphere(" + std::to_string(opt.subdivisions) + ")" : opt.input;
  std::printf("triangle input: %s, %zu vertices, %zu triangles\n", source.c_str(), triangles.points.size(),
              triangles.triangles.size());
  std::printf("quad input: torus(%d), %zu vertices, %zu quads\n", opt.torus, quads.points.size(),
              quads.quads.size());
  std::printf("vv: the translated examples/<scheme>.vvp, compiled as the interpreter compiles models\n"
              "(-O1), steps timed; vvlib: Loop written in C++ against vvlib (-O2)\n\n");

  const scratch_dir scratch;
  const bench_input warm_triangles = make_icosphere(0), warm_quads = make_quad_torus(3);
  const auto levels = [&](int fallback) { return opt.levels ? opt.levels : fallback; };
  bool agree = true;
  for (const std::string& name : opt.schemes) {
    scheme_run s{name, &triangles, levels(3), {}};
    const bench_input* warm = &warm_triangles;
    if (name == "loop") {
      s.contenders = {{"openmesh", run_openmesh_loop, true},
                      {"vv", translated("loop", "pyramid.vvm", scratch.path), true},
                      {"vvlib", run_vvlib_loop, true},
                      {"cgal", run_cgal_loop, true},
                      {"opensubdiv", run_opensubdiv_loop, true}};
    } else if (name == "catmull_clark") {
      s.input = &quads;
      warm = &warm_quads;
      s.contenders = {{"openmesh", run_openmesh_catmull_clark, true},
                      {"vv", translated("catmull_clark", "cube.vvm", scratch.path), true},
                      {"cgal", run_cgal_catmull_clark, true},
                      {"opensubdiv", run_opensubdiv_catmull_clark, true}};
    } else if (name == "sqrt3") {
      s.levels = levels(4);
      s.contenders = {{"openmesh", run_openmesh_sqrt3, true},
                      {"vv", translated("sqrt3", "icosahedron.vvm", scratch.path), true},
                      {"cgal", run_cgal_sqrt3, true}};
    } else if (name == "doo_sabin") {
      s.input = &quads;
      warm = &warm_quads;
      s.contenders = {{"cgal", run_cgal_doo_sabin, true},
                      {"vv", translated("doo_sabin", "cube.vvm", scratch.path), true}};
    } else {
      // OpenMesh's is Zorin's modified butterfly, which differs from the
      // original (the example's) around vertices of valence other than 6.
      s.contenders = {{"openmesh", run_openmesh_butterfly, true},
                      {"vv", translated("butterfly", "icosahedron.vvm", scratch.path), false}};
    }
    agree = run_scheme(s, opt.runs, *warm) && agree;
  }
  return agree ? 0 : 1;
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
