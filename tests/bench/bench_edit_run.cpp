// Continuous modelling speed: from a saved .vvp to its running model
// (translate, compile, load, start), as `vvinterpreter --batch` does it.
//
//   bench_edit_run [--runs R] [--interpreter PATH] [MODEL.vvp ...]   (default: the examples)
//
// --interpreter times another build of vvinterpreter (to compare before and
// after a change).
//
// For each model, in a scratch copy with a fresh cache:
//   first   — nothing cached, not even the precompiled vvlib header (the
//             declarations' part is compiled beside the program, as the
//             viewer does: --expect-edits);
//   edited  — the model changed, the header is precompiled (the usual case
//             while modelling: save and see);
//   cached  — unchanged, the compiled model is reused.
// Ends with one line per model: edit_run model=... first_ms=... edited_ms=... cached_ms=...
// edited_cpu_ms=... and, for several models, the median of their edited
// times (the target of continuous modelling: under a second on the
// project's 2-core machine). The CPU time (the interpreter's and its
// compilers', user and system) is a figure to compare while others load
// the machine, when wall-clock times are not.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../interpreter/run_interpreter.hpp"

namespace fs = std::filesystem;

namespace {

std::string interpreter = VV_INTERPRETER;

// The CPU time of the finished children (and theirs), in ms.
double children_cpu_ms() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  auto ms = [](const timeval& t) { return t.tv_sec * 1000.0 + t.tv_usec / 1000.0; };
  return ms(u.ru_utime) + ms(u.ru_stime);
}

struct timing {
  double wall_ms = 0, cpu_ms = 0;
};

timing timed_run(const std::string& model, const std::string& cache, bool& ok) {
  auto t = std::chrono::steady_clock::now();
  double cpu = children_cpu_ms();
  // --expect-edits: the declarations' part from the first build, as the
  // viewer makes it, so every edit below is the steady modelling loop.
  test_run::result r = test_run::run({interpreter, "--batch", "--quiet", "--expect-edits", "--cache", cache, model}, 300);
  ok = ok && r.status == 0;
  if (r.status != 0) std::fprintf(stderr, "%s", r.err.c_str());
  return {std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count(),
          children_cpu_ms() - cpu};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

const char* const usage = "usage: bench_edit_run [--runs R] [--interpreter PATH] [MODEL.vvp ...]   (default: the examples)\n";

int main(int argc, char** argv) {
  int runs = 3;
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--interpreter" && i + 1 < argc) interpreter = argv[++i];
    else if (a == "--help" || a == "-h") return std::printf("%s", usage), 0;
    else if (!a.empty() && a[0] == '-') return std::fprintf(stderr, "bench_edit_run: unknown option %s\n%s", a.c_str(), usage), 2;
    else models.push_back(a);
  }
  // Every model is checked before any is timed: a typo ends the run at once.
  for (const std::string& m : models) {
    std::error_code ec;
    if (!fs::is_regular_file(m, ec))
      return std::fprintf(stderr, "bench_edit_run: %s: no such model file\n", m.c_str()), 2;
  }
  if (models.empty()) {
    for (const auto& e : fs::directory_iterator(std::string(VV_SOURCE_DIR) + "/examples"))
      if (e.path().extension() == ".vvp") models.push_back(e.path().string());
    std::sort(models.begin(), models.end());
  }
  bool ok = true;
  std::vector<std::string> summary;
  std::vector<double> edited_medians, edited_cpu_medians;
  for (const std::string& source : models) {
    // A scratch copy beside a copy of models/, so relative inputs resolve.
    fs::path scratch = fs::temp_directory_path() / ("vv_bench_edit_run_" + std::to_string(getpid()));
    fs::remove_all(scratch);
    fs::create_directories(scratch / "examples");
    fs::copy(std::string(VV_SOURCE_DIR) + "/models", scratch / "models", fs::copy_options::recursive);
    std::string model = (scratch / "examples" / fs::path(source).filename()).string();
    fs::copy_file(source, model);
    std::string cache = (scratch / "cache").string();

    double first = timed_run(model, cache, ok).wall_ms;
    std::vector<double> edited, edited_cpu, cached;
    for (int r = 0; r < runs; ++r) {
      // A change to the code (a comment alone would not change the C++).
      std::ofstream(model, std::ios::app) << "[[maybe_unused]] static const int edit_" << r << " = " << r << ";\n";
      timing e = timed_run(model, cache, ok);
      edited.push_back(e.wall_ms);
      edited_cpu.push_back(e.cpu_ms);
      cached.push_back(timed_run(model, cache, ok).wall_ms);
    }
    fs::remove_all(scratch);
    std::string name = fs::path(source).filename().string();
    std::printf("%s: first run %.0f ms, after an edit %.0f ms (CPU %.0f ms; medians of %d), cached %.0f ms; target: under 1000 ms after an edit\n",
                name.c_str(), first, median(edited), median(edited_cpu), runs, median(cached));
    char line[256];
    std::snprintf(line, sizeof line, "edit_run model=%s first_ms=%.0f edited_ms=%.0f cached_ms=%.0f edited_cpu_ms=%.0f",
                  name.c_str(), first, median(edited), median(cached), median(edited_cpu));
    summary.push_back(line);
    edited_medians.push_back(median(edited));
    edited_cpu_medians.push_back(median(edited_cpu));
  }
  for (const std::string& s : summary) std::printf("%s\n", s.c_str());
  if (edited_medians.size() > 1)
    std::printf("edit_run models=%zu median_edited_ms=%.0f median_edited_cpu_ms=%.0f (target: under 1000 ms)\n",
                edited_medians.size(), median(edited_medians), median(edited_cpu_medians));
  return ok ? 0 : 1;
}
