// Continuous modelling speed: from a saved .vvp to its running model
// (translate, compile, load, start), as `vvinterpreter --batch` does it.
//
//   bench_edit_run [--runs R] [--interpreter PATH] [MODEL.vvp ...]   (default: the examples)
//
// --interpreter times another build of vvinterpreter (to compare before and
// after a change).
//
// For each model, in a scratch copy with a fresh cache:
//   first   — nothing cached, not even the precompiled vvlib header;
//   edited  — the model changed, the header is precompiled (the usual case
//             while modelling: save and see);
//   cached  — unchanged, the compiled model is reused.
// Ends with one line per model: edit_run model=... first_ms=... edited_ms=... cached_ms=...
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

double timed_run(const std::string& model, const std::string& cache, bool& ok) {
  auto t = std::chrono::steady_clock::now();
  test_run::result r = test_run::run({interpreter, "--batch", "--quiet", "--cache", cache, model}, 300);
  ok = ok && r.status == 0;
  if (r.status != 0) std::fprintf(stderr, "%s", r.err.c_str());
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--interpreter" && i + 1 < argc) interpreter = argv[++i];
    else models.push_back(a);
  }
  if (models.empty()) {
    for (const auto& e : fs::directory_iterator(std::string(VV_SOURCE_DIR) + "/examples"))
      if (e.path().extension() == ".vvp") models.push_back(e.path().string());
    std::sort(models.begin(), models.end());
  }
  bool ok = true;
  std::vector<std::string> summary;
  for (const std::string& source : models) {
    // A scratch copy beside a copy of models/, so relative inputs resolve.
    fs::path scratch = fs::temp_directory_path() / ("vv_bench_edit_run_" + std::to_string(getpid()));
    fs::remove_all(scratch);
    fs::create_directories(scratch / "examples");
    fs::copy(std::string(VV_SOURCE_DIR) + "/models", scratch / "models", fs::copy_options::recursive);
    std::string model = (scratch / "examples" / fs::path(source).filename()).string();
    fs::copy_file(source, model);
    std::string cache = (scratch / "cache").string();

    double first = timed_run(model, cache, ok);
    std::vector<double> edited, cached;
    for (int r = 0; r < runs; ++r) {
      // A change to the code (a comment alone would not change the C++).
      std::ofstream(model, std::ios::app) << "[[maybe_unused]] static const int edit_" << r << " = " << r << ";\n";
      edited.push_back(timed_run(model, cache, ok));
      cached.push_back(timed_run(model, cache, ok));
    }
    fs::remove_all(scratch);
    std::string name = fs::path(source).filename().string();
    std::printf("%s: first run %.0f ms, after an edit %.0f ms (median of %d), cached %.0f ms; target: under 2000 ms after an edit\n",
                name.c_str(), first, median(edited), runs, median(cached));
    char line[256];
    std::snprintf(line, sizeof line, "edit_run model=%s first_ms=%.0f edited_ms=%.0f cached_ms=%.0f", name.c_str(),
                  first, median(edited), median(cached));
    summary.push_back(line);
  }
  for (const std::string& s : summary) std::printf("%s\n", s.c_str());
  return ok ? 0 : 1;
}
