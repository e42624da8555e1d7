// What the viewer tests share: files, exported meshes, screenshots, and
// running the viewer in a virtual display (whole, or live while the test
// edits its files).
#pragma once

#include <vv/vv.hpp>
#include <vv/invariants.hpp>
#include <vv/io/vvm.hpp>
#include <util/point.hpp>
#include <stb/stb_image.h>
#include <gtest/gtest.h>
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
#include "run_interpreter.hpp"
#include "test_files.hpp"

using test_files::scratch_dir;
using test_files::slurp;

namespace viewer_harness {

namespace fs = std::filesystem;

inline const std::string models_dir = VV_TESTS_DIR "/viewer_models/";
inline const std::string loop_model = VV_SOURCE_DIR "/examples/loop.vvp";

// The viewer opens its window at this size (vvinterpreter/viewer.cpp); Xvfb
// has no window manager to change it.
constexpr int window_width = 1100, window_height = 800;

// Model compiles take a few seconds (the first one also builds the shared
// precompiled header), so every run gets a generous limit.
constexpr int viewer_timeout = 240;

// ---- files ----

//! A fresh folder in the scratch area for one test.
inline std::string fresh_dir(const std::string& name) {
  std::string d = scratch_dir() + name + "/";
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

//! Replaces a file the way editors do: write a temporary, rename over it,
//! so the viewer's file watch never sees a half-written model.
inline void replace_file(const std::string& path, const std::string& text) {
  std::string tmp = path + ".tmp";
  write_text(tmp, text);
  fs::rename(tmp, path);
}

//! `text` with its one occurrence of `from` replaced by `to`.
inline std::string edited(const std::string& text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the model";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' twice in the model";
  if (at == std::string::npos) return text;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

//! The 1-based number of the line of `text` holding `needle`.
inline int line_of(const std::string& text, const std::string& needle) {
  std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << "'" << needle << "' is not in the model";
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

inline std::string script(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

// ---- exported meshes ----

using Pt = util::Point<double>;
struct PosOnly {
  Pt pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using PG = vv::graph<PosOnly>;

//! The number of vertices of an exported .vvm file (-1 when it cannot be
//! read); its structure must be valid.
inline long vvm_vertex_count(const std::string& path) {
  if (!fs::exists(path)) {
    ADD_FAILURE() << "no file " << path;
    return -1;
  }
  PG::context ctx;
  PG::mesh m(ctx);
  try {
    vv::read_vvm(m, path);
    vv::check_invariants(m);
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": " << e.what();
    return -1;
  }
  return static_cast<long>(m.size());
}

// ---- screenshots ----

struct image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 3 bytes a pixel, rows top down
  bool ok() const { return width > 0 && height > 0; }
  const unsigned char* at(int x, int y) const {
    return &rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
  }
};

inline image load_png(const std::string& path) {
  image im;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &im.width, &im.height, &channels, 3);
  if (!data) {
    ADD_FAILURE() << "cannot read the PNG " << path << ": " << stbi_failure_reason();
    im.width = im.height = 0;
    return im;
  }
  im.rgb.assign(data, data + 3 * static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.height));
  stbi_image_free(data);
  return im;
}

//! Where the picture differs from its background (the colour of its top
//! left corner).
struct box {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive; empty when x1 < x0
  long pixels = 0;                        // how many pixels are not background
  bool empty() const { return x1 < x0; }
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};

inline bool near_colour(const unsigned char* a, const unsigned char* b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a[c]) - int(b[c])) > 8) return false;
  return true;
}

inline box object_box(const image& im) {
  box b;
  b.x0 = im.width, b.y0 = im.height;
  const unsigned char* background = im.at(0, 0);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      if (near_colour(im.at(x, y), background)) continue;
      ++b.pixels;
      b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
      b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
    }
  if (b.pixels == 0) b = box();
  return b;
}

inline std::string describe(const box& b) {
  std::ostringstream s;
  s << "[" << b.x0 << ".." << b.x1 << "] x [" << b.y0 << ".." << b.y1 << "], " << b.pixels << " pixels";
  return s.str();
}

//! A screenshot of the viewer's scene: the window's size, a plain
//! background in all four corners, and an object that covers a fair part
//! of the picture without touching its edges.
inline void expect_scene_shot(const std::string& path) {
  SCOPED_TRACE(path);
  image im = load_png(path);
  ASSERT_TRUE(im.ok());
  EXPECT_EQ(im.width, window_width);
  EXPECT_EQ(im.height, window_height);
  const unsigned char* corner = im.at(0, 0);
  EXPECT_TRUE(near_colour(im.at(im.width - 1, 0), corner) && near_colour(im.at(0, im.height - 1), corner) &&
              near_colour(im.at(im.width - 1, im.height - 1), corner))
      << "the corners differ: not a plain background";
  box b = object_box(im);
  ASSERT_FALSE(b.empty()) << "blank screenshot";
  EXPECT_GT(b.pixels, long(im.width) * im.height / 100) << describe(b);
  EXPECT_GT(b.x0, 0) << describe(b);
  EXPECT_GT(b.y0, 0) << describe(b);
  EXPECT_LT(b.x1, im.width - 1) << describe(b);
  EXPECT_LT(b.y1, im.height - 1) << describe(b);
  // The camera fits the object, so it sits in the middle (a control panel
  // drawn into the picture would pull the box to one side).
  EXPECT_NEAR((b.x0 + b.x1) / 2.0, im.width / 2.0, im.width / 10.0) << describe(b);
  EXPECT_NEAR((b.y0 + b.y1) / 2.0, im.height / 2.0, im.height / 10.0) << describe(b);
}

// ---- running the viewer ----

//! vvinterpreter in its window (inside Xvfb) with the given arguments.
inline test_run::result viewer(const std::vector<std::string>& args) {
  return test_run::run(test_run::in_virtual_display(test_run::interpreter(args)), viewer_timeout);
}

inline std::string report(const test_run::result& r) {
  return "status " + std::to_string(r.status) + (r.timed_out ? " (timed out)" : "") + "\n--- stdout:\n" +
         r.out + "--- stderr:\n" + r.err;
}

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

//! How many times part occurs in text (overlapping occurrences count).
inline int count_of(const std::string& text, const std::string& part) {
  int n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

//! The lines of stderr that are the viewer's own messages.
inline std::vector<std::string> viewer_errors(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string l; std::getline(in, l);)
    if (l.rfind("vvinterpreter: ", 0) == 0) lines.push_back(l);
  return lines;
}

//! Whether one of the viewer's error lines names `where` (e.g.
//! "model.vvp:12") as the place of the error: followed by ':' (a column or
//! the message), not by more digits.
inline bool error_names(const std::string& err, const std::string& where) {
  for (const std::string& l : viewer_errors(err)) {
    for (std::size_t at = l.find(where); at != std::string::npos; at = l.find(where, at + 1)) {
      std::size_t after = at + where.size();
      if (after < l.size() && l[after] == ':') return true;
    }
  }
  return false;
}

//! A viewer started in the background, whose output the test reads while
//! it runs (to change files at the right moment).
class live_viewer {
 public:
  explicit live_viewer(const std::vector<std::string>& args) {
    std::vector<std::string> argv = test_run::in_virtual_display(test_run::interpreter(args));
    int out_pipe[2], err_pipe[2];
    if (pipe(out_pipe) != 0 || pipe(err_pipe) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out_pipe[1], STDOUT_FILENO);
      dup2(err_pipe[1], STDERR_FILENO);
      close(out_pipe[0]), close(err_pipe[0]), close(out_pipe[1]), close(err_pipe[1]);
      setpgid(0, 0);
      std::vector<char*> a;
      for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      execvp(a[0], a.data());
      _exit(127);
    }
    close(out_pipe[1]), close(err_pipe[1]);
    fds_[0] = {out_pipe[0], POLLIN, 0};
    fds_[1] = {err_pipe[0], POLLIN, 0};
    deadline_ = std::chrono::steady_clock::now() + std::chrono::seconds(viewer_timeout);
  }

  ~live_viewer() {
    if (pid_ > 0 && !reaped_) {
      kill(-pid_, SIGKILL);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    for (pollfd& f : fds_)
      if (f.fd >= 0) close(f.fd);
  }

  //! Reads output until stdout holds `part` (true) or the output ends or
  //! `seconds` pass (false).
  bool wait_for_out(const std::string& part, int seconds) {
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (!has(out, part)) {
      if (std::chrono::steady_clock::now() >= until || !pump(until)) return has(out, part);
    }
    return true;
  }

  //! Waits for the viewer to end (killing it after the overall time
  //! limit) and gives its exit status (-1 when killed).
  test_run::result finish() {
    while (pump(deadline_)) {
    }
    test_run::result r;
    if (std::chrono::steady_clock::now() >= deadline_ && (fds_[0].fd >= 0 || fds_[1].fd >= 0)) {
      r.timed_out = true;
      kill(-pid_, SIGKILL);
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    r.status = (!r.timed_out && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    r.out = out, r.err = err;
    return r;
  }

  bool started() const { return pid_ > 0; }

  std::string out, err;

 private:
  // Reads what is there (waiting at most until `until`); false when both
  // pipes are closed or the time is up.
  bool pump(std::chrono::steady_clock::time_point until) {
    if (fds_[0].fd < 0 && fds_[1].fd < 0) return false;
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    if (poll(fds_, 2, static_cast<int>(std::min<long>(left.count(), 200))) <= 0) return true;
    for (int i = 0; i < 2; ++i) {
      if (fds_[i].fd < 0 || !(fds_[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      ssize_t n = read(fds_[i].fd, buf, sizeof buf);
      if (n > 0) (i == 0 ? out : err).append(buf, static_cast<std::size_t>(n));
      else close(fds_[i].fd), fds_[i].fd = -1;
    }
    return true;
  }

  pid_t pid_ = -1;
  bool reaped_ = false;
  pollfd fds_[2] = {{-1, 0, 0}, {-1, 0, 0}};
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace viewer_harness

using namespace viewer_harness;
