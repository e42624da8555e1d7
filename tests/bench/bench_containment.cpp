// The cost of running models supervised (a crash or a hang never takes the
// interpreter down): Loop subdivision of the double pyramid to 2,097,152
// triangles (examples/loop.vvp, 9 steps), then drawing it (an offscreen
// screenshot), supervised as always, and in the interpreter's own process
// (--in-process, as it ran before supervision). With --baseline PATH, an
// interpreter of another build is timed too, on the same model.
//
//   bench_containment [--runs R] [--steps N] [--baseline VVINTERPRETER]
//
// Ends with: containment supervised_ms=... in_process_ms=... ratio=... [baseline_ms=... vs_baseline=...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../interpreter/run_interpreter.hpp"

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One batch run; its wall time (ms), or a negative number when it failed.
double timed(const std::vector<std::string>& argv) {
  auto t = std::chrono::steady_clock::now();
  test_run::result r = test_run::run(argv, 600);
  double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  if (r.status != 0) {
    std::fprintf(stderr, "failed: %s", r.err.c_str());
    return -1;
  }
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  std::string steps = "9", baseline;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--steps" && i + 1 < argc) steps = argv[++i];
    else if (a == "--baseline" && i + 1 < argc) baseline = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_containment [--runs R] [--steps N] [--baseline VVINTERPRETER]\n");
      return 2;
    }
  }
  fs::path scratch = fs::temp_directory_path() / ("vv_bench_containment_" + std::to_string(getpid()));
  fs::create_directories(scratch);
  std::string model = std::string(VV_SOURCE_DIR) + "/examples/loop.vvp";
  auto command = [&](const std::string& interpreter, const std::string& cache, bool in_process) {
    std::vector<std::string> a = {interpreter, "--batch", "--quiet", "--cache", cache, "--steps", steps,
                                  "--screenshot", (scratch / "shot.png").string(), model};
    if (in_process) a.insert(a.begin() + 2, "--in-process");
    return a;
  };
  std::string cache = (scratch / "cache").string(), baseline_cache = (scratch / "baseline-cache").string();
  // Compile once for each, outside the timing.
  bool ok = timed(command(VV_INTERPRETER, cache, false)) >= 0;
  if (!baseline.empty()) ok = ok && timed(command(baseline, baseline_cache, false)) >= 0;
  std::vector<double> supervised, in_process, base;
  for (int r = 0; r < runs && ok; ++r) {
    // Interleaved, so a slower moment of the machine hits all alike.
    supervised.push_back(timed(command(VV_INTERPRETER, cache, false)));
    in_process.push_back(timed(command(VV_INTERPRETER, cache, true)));
    if (!baseline.empty()) base.push_back(timed(command(baseline, baseline_cache, false)));
    for (double t : {supervised.back(), in_process.back()}) ok = ok && t >= 0;
    if (!base.empty()) ok = ok && base.back() >= 0;
  }
  fs::remove_all(scratch);
  if (!ok) return 1;
  double s = median(supervised), p = median(in_process);
  std::printf("loop.vvp, %s steps, then a screenshot; median of %d runs\n", steps.c_str(), runs);
  std::printf("supervised %.0f ms, in-process %.0f ms: supervision costs %+.1f%% (target: at most 10%%)\n", s, p,
              (s / p - 1) * 100);
  std::printf("containment supervised_ms=%.0f in_process_ms=%.0f ratio=%.3f", s, p, s / p);
  if (!base.empty()) std::printf(" baseline_ms=%.0f vs_baseline=%.3f", median(base), s / median(base));
  std::printf("\n");
  return 0;
}
