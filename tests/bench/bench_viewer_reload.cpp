// Continuous modelling in the viewer: from saving a .vvp to the new model
// drawn, in the real viewer inside a virtual display (Xvfb).
//
//   bench_viewer_reload [--runs R] [--steps N] [--interpreter PATH] [MODEL.vvp ...]
//   (default: examples/loop.vvp and examples/korn_spalding.vvp)
//
// For each model, in a scratch copy with a fresh cache, the viewer starts
// and runs N steps (default 2). Then the model is saved R times (default
// 5), each time with a change to its code below the property blocks, as
// an editor saves (a new file renamed over the old). Each save is timed
// until the viewer prints "reloaded": the new model has been compiled,
// loaded and run again to the step the old one was at, and that frame
// draws it. The time includes the viewer's file watch, which hears of a
// save at once (inotify) and looks every quarter of a second besides.
// Ends with one line per model: viewer_reload model=... median_ms=... min_ms=... max_ms=...
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../interpreter/run_interpreter.hpp"

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

namespace {

std::string interpreter = VV_INTERPRETER;

// The viewer running in the background; its standard output is read as it
// comes (standard error is left to the terminal).
class running_viewer {
 public:
  explicit running_viewer(const std::vector<std::string>& argv) {
    int ends[2];
    if (pipe(ends) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(ends[1], STDOUT_FILENO);
      close(ends[0]);
      close(ends[1]);
      setpgid(0, 0);  // the viewer, its supervisor and Xvfb end together
      std::vector<char*> a;
      for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      execvp(a[0], a.data());
      _exit(127);
    }
    close(ends[1]);
    fd_ = ends[0];
  }
  ~running_viewer() { stop(); }

  //! Ends the viewer, its supervisor and Xvfb (before the files they use
  //! are removed: the viewer would hear of it and reload).
  void stop() {
    if (pid_ > 0) {
      kill(-pid_, SIGKILL);
      int status = 0;
      waitpid(pid_, &status, 0);
      pid_ = -1;
    }
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
  }

  //! Reads until the output holds `part` `count` times (true), or it ends
  //! or `seconds` pass (false).
  bool wait_for(const std::string& part, std::size_t count, int seconds) {
    auto until = clock_type::now() + std::chrono::seconds(seconds);
    while (occurrences(part) < count) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - clock_type::now()).count();
      if (left <= 0 || fd_ < 0) return false;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(std::min<long>(left, 100))) <= 0) continue;
      char buf[4096];
      ssize_t n = read(fd_, buf, sizeof buf);
      if (n <= 0) {
        close(fd_);
        fd_ = -1;
      } else {
        out.append(buf, static_cast<std::size_t>(n));
      }
    }
    return true;
  }

  std::size_t occurrences(const std::string& part) const {
    std::size_t n = 0;
    for (std::size_t at = out.find(part); at != std::string::npos; at = out.find(part, at + 1)) ++n;
    return n;
  }

  bool started() const { return pid_ > 0; }
  std::string out;

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

const char* const usage =
    "usage: bench_viewer_reload [--runs R] [--steps N] [--interpreter PATH] [MODEL.vvp ...]\n"
    "       (default: examples/loop.vvp and examples/korn_spalding.vvp)\n";

int main(int argc, char** argv) {
  int runs = 5, steps = 2;
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--steps" && i + 1 < argc) steps = std::max(0, std::atoi(argv[++i]));
    else if (a == "--interpreter" && i + 1 < argc) interpreter = argv[++i];
    else if (a == "--help" || a == "-h") return std::printf("%s", usage), 0;
    else if (!a.empty() && a[0] == '-')
      return std::fprintf(stderr, "bench_viewer_reload: unknown option %s\n%s", a.c_str(), usage), 2;
    else models.push_back(a);
  }
  // Every model is checked before any is timed: a typo ends the run at once.
  for (const std::string& m : models) {
    std::error_code ec;
    if (!fs::is_regular_file(m, ec))
      return std::fprintf(stderr, "bench_viewer_reload: %s: no such model file\n", m.c_str()), 2;
  }
  if (models.empty())
    for (const char* m : {"loop.vvp", "korn_spalding.vvp"}) models.push_back(std::string(VV_SOURCE_DIR) + "/examples/" + m);
  bool ok = true;
  std::vector<std::string> summary;
  for (const std::string& source : models) {
    // A scratch copy beside a copy of models/, so relative inputs resolve.
    fs::path scratch = fs::temp_directory_path() / ("vv_bench_viewer_reload_" + std::to_string(getpid()));
    fs::remove_all(scratch);
    fs::create_directories(scratch / "examples");
    fs::copy(std::string(VV_SOURCE_DIR) + "/models", scratch / "models", fs::copy_options::recursive);
    const std::string model = (scratch / "examples" / fs::path(source).filename()).string();
    fs::copy_file(source, model);
    const std::string shot = (scratch / "ready.png").string();
    std::ofstream(scratch / "script.txt") << "step " << steps << "\nscreenshot " << shot << "\nwait 3600000\nquit\n";
    running_viewer v(test_run::in_virtual_display(
        {interpreter, "--cache", (scratch / "cache").string(), "--script", (scratch / "script.txt").string(), model}));
    std::string name = fs::path(source).filename().string();
    std::vector<double> times;
    if (!v.started() || !v.wait_for("wrote " + shot, 1, 600)) {
      std::fprintf(stderr, "%s: the viewer did not start and run %d steps:\n%s", name.c_str(), steps, v.out.c_str());
      ok = false;
    }
    std::string text;
    {
      std::ifstream in(model);
      std::stringstream s;
      s << in.rdbuf();
      text = s.str();
    }
    for (int r = 0; ok && r < runs; ++r) {
      // A change to the code (a comment alone reloads the cached build),
      // saved as editors do.
      text += "[[maybe_unused]] static const int edit_" + std::to_string(r) + " = " + std::to_string(r) + ";\n";
      std::ofstream(model + ".tmp") << text;
      auto saved = clock_type::now();
      fs::rename(model + ".tmp", model);
      if (!v.wait_for("reloaded " + model, static_cast<std::size_t>(r + 1), 600)) {
        std::fprintf(stderr, "%s: no reload after save %d:\n%s", name.c_str(), r + 1, v.out.c_str());
        ok = false;
        break;
      }
      times.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - saved).count());
    }
    v.stop();
    fs::remove_all(scratch);
    if (times.empty()) continue;
    std::printf("%s: save -> new model drawn at step %d: %.0f ms (median of %zu: %.0f .. %.0f); target: under 1500 ms\n",
                name.c_str(), steps, median(times), times.size(), *std::min_element(times.begin(), times.end()),
                *std::max_element(times.begin(), times.end()));
    char line[256];
    std::snprintf(line, sizeof line, "viewer_reload model=%s median_ms=%.0f min_ms=%.0f max_ms=%.0f", name.c_str(),
                  median(times), *std::min_element(times.begin(), times.end()),
                  *std::max_element(times.begin(), times.end()));
    summary.push_back(line);
  }
  for (const std::string& s : summary) std::printf("%s\n", s.c_str());
  return ok ? 0 : 1;
}
