// vvinterpreter: build, load and run vv models — in a window, or headless
// for regression tests (see docs/interpreter.md).
#include <cstdio>
#include <cstdlib>

#include "batch/batch.hpp"
#include "app/options.hpp"
#include "experiment/sweep.hpp"
#include "series/movie.hpp"
#include "series/step_names.hpp"
#include "viewer/viewer.hpp"

int main(int argc, char** argv) {
  // A model's parallel loops (OpenMP, loaded with the model after this)
  // wait at their ends. libgomp's default spins there for long: on a busy
  // machine the spinning thread keeps the one it waits for off the CPU, and
  // a loop takes ten times longer than on one thread. A short spin, then
  // sleep, unless the user chose otherwise.
  if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT")) setenv("GOMP_SPINCOUNT", "10000", 0);
  vvi::parse_result p = vvi::parse_options(argc, argv);
  if (!p.ok) {
    std::fprintf(stderr, "%s", p.message.c_str());
    return 2;
  }
  if (p.exit_now) {
    std::printf("%s", p.message.c_str());
    return 0;
  }
  if (p.opts.sweep.merging()) return vvi::run_merge(p.opts);
  // A movie needs ffmpeg: said before anything runs (a sweep: before its runs).
  if (p.opts.batch && vvi::series_file_of(p.opts.screenshot) == vvi::series_file::movie)
    if (std::string why = vvi::movie_maker_missing(p.opts.screenshot); !why.empty()) {
      std::fprintf(stderr, "vvinterpreter: %s\n", why.c_str());
      return 1;
    }
  if (p.opts.sweep.sweeping()) return vvi::run_sweep(p.opts, argc, argv);
  if (p.opts.compile_only) return vvi::run_compile_only(p.opts);
  if (p.opts.batch) return vvi::run_batch(p.opts);
  return vvi::run_viewer(p.opts);
}
