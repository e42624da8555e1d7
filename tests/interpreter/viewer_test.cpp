// The interactive viewer (vvinterpreter without --batch), driven through
// --script inside a virtual X display: scripted sessions (steps, rewind,
// screenshots, export, camera), continuous modelling (editing the model
// while the window is open), errors that must leave the window running,
// proxy.record_frame, and the message when there is no display at all.
//
// Small models live in viewer_models/; files the viewer writes go to the
// scratch folder of this test process.
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

namespace {

namespace fs = std::filesystem;

const std::string models_dir = VV_TESTS_DIR "/viewer_models/";
const std::string loop_model = VV_SOURCE_DIR "/examples/loop.vvp";

// The viewer opens its window at this size (vvinterpreter/viewer.cpp); Xvfb
// has no window manager to change it.
constexpr int window_width = 1100, window_height = 800;

// Model compiles take a few seconds (the first one also builds the shared
// precompiled header), so every run gets a generous limit.
constexpr int viewer_timeout = 240;

// ---- files ----

//! A fresh folder in the scratch area for one test.
std::string fresh_dir(const std::string& name) {
  std::string d = scratch_dir() + name + "/";
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

//! Replaces a file the way editors do: write a temporary, rename over it,
//! so the viewer's file watch never sees a half-written model.
void replace_file(const std::string& path, const std::string& text) {
  std::string tmp = path + ".tmp";
  write_text(tmp, text);
  fs::rename(tmp, path);
}

//! `text` with its one occurrence of `from` replaced by `to`.
std::string edited(const std::string& text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the model";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' twice in the model";
  if (at == std::string::npos) return text;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

//! The 1-based number of the line of `text` holding `needle`.
int line_of(const std::string& text, const std::string& needle) {
  std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << "'" << needle << "' is not in the model";
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::string script(const std::vector<std::string>& lines) {
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
long vvm_vertex_count(const std::string& path) {
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

image load_png(const std::string& path) {
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

bool near_colour(const unsigned char* a, const unsigned char* b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a[c]) - int(b[c])) > 8) return false;
  return true;
}

box object_box(const image& im) {
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

std::string describe(const box& b) {
  std::ostringstream s;
  s << "[" << b.x0 << ".." << b.x1 << "] x [" << b.y0 << ".." << b.y1 << "], " << b.pixels << " pixels";
  return s.str();
}

//! A screenshot of the viewer's scene: the window's size, a plain
//! background in all four corners, and an object that covers a fair part
//! of the picture without touching its edges.
void expect_scene_shot(const std::string& path) {
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
test_run::result viewer(const std::vector<std::string>& args) {
  return test_run::run(test_run::in_virtual_display(test_run::interpreter(args)), viewer_timeout);
}

std::string report(const test_run::result& r) {
  return "status " + std::to_string(r.status) + (r.timed_out ? " (timed out)" : "") + "\n--- stdout:\n" +
         r.out + "--- stderr:\n" + r.err;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

//! The lines of stderr that are the viewer's own messages.
std::vector<std::string> viewer_errors(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string l; std::getline(in, l);)
    if (l.rfind("vvinterpreter: ", 0) == 0) lines.push_back(l);
  return lines;
}

//! Whether one of the viewer's error lines names `where` (e.g.
//! "model.vvp:12") as the place of the error: followed by ':' (a column or
//! the message), not by more digits.
bool error_names(const std::string& err, const std::string& where) {
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

// ---- 1. a scripted session ----

TEST(ViewerScript, StepsRewindScreenshotsExportCameraAndQuit) {
  std::string d = fresh_dir("session");
  std::string a = d + "a.png", b = d + "b.png", rotated = d + "rotated.png", zoomed = d + "zoomed.png";
  std::string exported = d + "S.vvm";
  write_text(d + "session.txt", script({"step 2", "screenshot " + a, "rewind", "step 2", "screenshot " + b,
                                        "export S " + exported, "rotate 30 20", "screenshot " + rotated,
                                        "zoom 2", "screenshot " + zoomed, "quit"}));
  test_run::result r = viewer({"--script", d + "session.txt", loop_model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  EXPECT_TRUE(has(r.out, "loaded " + loop_model)) << report(r);
  EXPECT_TRUE(has(r.out, "rewound " + loop_model)) << report(r);
  for (const std::string& f : {a, b, exported, rotated, zoomed})
    EXPECT_TRUE(has(r.out, "wrote " + f)) << report(r);

  // Two steps after a rewind draw exactly what two steps after loading drew.
  ASSERT_TRUE(fs::exists(a) && fs::exists(b)) << report(r);
  EXPECT_TRUE(slurp(a) == slurp(b)) << "the screenshots after rewind and the same steps differ";
  expect_scene_shot(a);
  expect_scene_shot(b);

  // The mesh after two Loop steps of the double pyramid.
  EXPECT_EQ(vvm_vertex_count(exported), 66);

  // Turning the camera changes the picture.
  ASSERT_TRUE(fs::exists(rotated)) << report(r);
  EXPECT_FALSE(slurp(rotated) == slurp(b)) << "rotate 30 20 did not change the screenshot";
  expect_scene_shot(rotated);

  // Zooming in by 2 makes the object larger in the picture.
  ASSERT_TRUE(fs::exists(zoomed)) << report(r);
  image before = load_png(rotated), after = load_png(zoomed);
  ASSERT_TRUE(before.ok() && after.ok());
  box small = object_box(before), large = object_box(after);
  ASSERT_FALSE(small.empty() || large.empty());
  EXPECT_GT(large.width(), small.width() * 3 / 2) << describe(small) << " -> " << describe(large);
  EXPECT_GT(large.height(), small.height() * 3 / 2) << describe(small) << " -> " << describe(large);
  EXPECT_GT(large.pixels, small.pixels * 2) << describe(small) << " -> " << describe(large);
}

// ---- 2. continuous modelling ----

TEST(ViewerHotReload, EditedModelReloadsAndABrokenEditKeepsTheLastGoodModel) {
  std::string d = fresh_dir("hot");
  std::string model = d + "grow.vvp";
  const std::string original = slurp(models_dir + "grow.vvp");
  write_text(model, original);
  const std::string before = d + "before.vvm", after = d + "after.vvm", last = d + "last.vvm";
  const std::string shot = d + "after_error.png";
  // Each wait leaves time for the file watch to notice an edit; the viewer
  // holds the script while it recompiles.
  write_text(d + "hot.txt", script({"step 2", "export M " + before, "wait 6000", "step 2", "export M " + after,
                                    "wait 6000", "step 1", "export M " + last, "screenshot " + shot, "quit"}));
  live_viewer v({"--script", d + "hot.txt", model});
  ASSERT_TRUE(v.started());

  // First edit, once the original model has run: 3 triangles a step, not 1.
  ASSERT_TRUE(v.wait_for_out("wrote " + before, viewer_timeout)) << v.out << v.err;
  EXPECT_TRUE(has(v.out, "loaded " + model)) << v.out;
  // (The new text is longer too, so a coarse file clock cannot hide the edit.)
  replace_file(model, edited(original, "const int per_step = 1;", "const int per_step = 3;  // was 1"));
  bool reloaded = v.wait_for_out("reloaded " + model, 120);
  EXPECT_TRUE(reloaded) << v.out << v.err;

  // Second edit, after the reloaded model has run: a syntax error.
  bool exported_after = v.wait_for_out("wrote " + after, 120);
  EXPECT_TRUE(exported_after) << v.out << v.err;
  std::string good = slurp(model);
  std::string broken = edited(good, "make {a, b} nb_of c;", "make {a, b} c;");
  int broken_line = line_of(broken, "make {a, b} c;");
  replace_file(model, broken);

  test_run::result r = v.finish();
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);

  // The original behaviour: a triangle from start and one a step.
  EXPECT_EQ(vvm_vertex_count(before), 3 + 2 * 3) << report(r);
  // Reloaded before the next steps ran: the reload starts the new model
  // afresh and runs it again to step 2, then two more steps: three
  // triangles a step, four steps.
  std::size_t reload_at = r.out.find("reloaded " + model), after_at = r.out.find("wrote " + after);
  EXPECT_TRUE(reload_at != std::string::npos && after_at != std::string::npos && reload_at < after_at)
      << report(r);
  EXPECT_EQ(vvm_vertex_count(after), 3 + 4 * 9) << report(r);
  EXPECT_EQ(r.out.find("reloaded " + model, reload_at + 1), std::string::npos)
      << "the broken edit was loaded\n" << report(r);

  // The syntax error is shown with its line; the last good model keeps
  // running: one more step of it adds three triangles.
  EXPECT_TRUE(error_names(r.err, "grow.vvp:" + std::to_string(broken_line))) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + last)) << report(r);
  EXPECT_EQ(vvm_vertex_count(last), 3 + 5 * 9) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + shot)) << report(r);
  if (fs::exists(shot)) {
    image im = load_png(shot);
    ASSERT_TRUE(im.ok());
    EXPECT_FALSE(object_box(im).empty()) << "the last good model is not drawn";
  }
}

// ---- 3. errors leave the window running ----

struct error_run {
  test_run::result result;
  std::string dir;
};

//! Runs `model` in the viewer with the script lines `before`, then an
//! export of M, a screenshot and quit; checks that the viewer went on
//! after the error (the screenshot was written) and quit normally.
error_run run_with_error(const std::string& name, const std::string& model, const std::vector<std::string>& before) {
  error_run e;
  e.dir = fresh_dir(name);
  std::vector<std::string> lines = before;
  lines.push_back("export M " + e.dir + "M.vvm");
  lines.push_back("screenshot " + e.dir + "after.png");
  lines.push_back("quit");
  write_text(e.dir + "script.txt", script(lines));
  e.result = viewer({"--script", e.dir + "script.txt", model});
  const test_run::result& r = e.result;
  EXPECT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_FALSE(viewer_errors(r.err).empty()) << "no error message\n" << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + e.dir + "after.png")) << "the viewer stopped working after the error\n"
                                                           << report(r);
  return e;
}

TEST(ViewerErrors, SyntaxErrorNamesTheLine) {
  std::string model = models_dir + "syntax_error.vvp";
  int line = line_of(slurp(model), "forall in M");
  error_run e = run_with_error("syntax", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "syntax_error.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

TEST(ViewerErrors, CompileErrorNamesTheLine) {
  std::string model = models_dir + "compile_error.vvp";
  int line = line_of(slurp(model), "no_such_variable");
  error_run e = run_with_error("compile", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "compile_error.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_TRUE(has(e.result.err, "no_such_variable")) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

TEST(ViewerErrors, RunTimeErrorInStepTwoKeepsTheStateAfterStepOne) {
  std::string model = models_dir + "runtime_error.vvp";
  int line = line_of(slurp(model), "make {a, b, a} nb_of c;");
  error_run e = run_with_error("runtime", model, {"step 3"});
  EXPECT_TRUE(has(e.result.out, "loaded " + model)) << report(e.result);
  EXPECT_TRUE(error_names(e.result.err, "runtime_error.vvp:" + std::to_string(line))) << report(e.result);
  // Step 1 added one vertex; step 2 failed before changing anything and
  // step 3 did not run.
  EXPECT_TRUE(has(e.result.out, "wrote " + e.dir + "M.vvm")) << report(e.result);
  EXPECT_EQ(vvm_vertex_count(e.dir + "M.vvm"), 1) << report(e.result);
}

TEST(ViewerErrors, MissingInputFileInStartNamesTheLine) {
  std::string model = models_dir + "missing_input.vvp";
  int line = line_of(slurp(model), "no_such_input.vvm");
  error_run e = run_with_error("missing_input", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "missing_input.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_TRUE(has(e.result.err, "no_such_input.vvm")) << report(e.result);
}

TEST(ViewerErrors, MissingModelFileIsReported) {
  std::string d = fresh_dir("missing_model_file");
  std::string model = d + "no_such_model.vvp";
  error_run e = run_with_error("missing_model", model, {"step 1"});
  bool named = false;
  for (const std::string& l : viewer_errors(e.result.err)) named = named || has(l, model);
  EXPECT_TRUE(named) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

// ---- 4. proxy.record_frame ----

TEST(ViewerRecordFrame, WritesOneNumberedFramePerStep) {
  std::string d = fresh_dir("record");
  std::string frames = d + "frames";  // the viewer creates it
  write_text(d + "record.txt", script({"step 3", "quit"}));
  test_run::result r = viewer({"--frames", frames, "--script", d + "record.txt", models_dir + "record_frame.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  std::vector<std::string> names;
  if (fs::is_directory(frames))
    for (const auto& entry : fs::directory_iterator(frames)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_00001.png", "frame_00002.png", "frame_00003.png"}))
      << report(r);
  std::vector<std::string> pngs;
  for (const std::string& n : names) {
    image im = load_png(frames + "/" + n);
    EXPECT_EQ(im.width, window_width) << n;
    EXPECT_EQ(im.height, window_height) << n;
    EXPECT_FALSE(object_box(im).empty()) << n << " is blank";
    pngs.push_back(slurp(frames + "/" + n));
  }
  // Each step adds a triangle in view: every frame shows a new state.
  for (std::size_t i = 0; i < pngs.size(); ++i)
    for (std::size_t j = i + 1; j < pngs.size(); ++j)
      EXPECT_FALSE(pngs[i] == pngs[j]) << names[i] << " and " << names[j] << " are the same picture";
}

// ---- 5. no display ----

TEST(ViewerWithoutDisplay, ExitsWithOneLineSuggestingBatch) {
  std::string d = fresh_dir("no_display");
  write_text(d + "quit.txt", script({"quit"}));
  test_run::result r = test_run::run(
      {"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", VV_INTERPRETER, "--cache", VV_TEST_CACHE, "--script",
       d + "quit.txt", models_dir + "grow.vvp"},
      viewer_timeout);
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  EXPECT_NE(r.status, -1) << "killed by a signal\n" << report(r);
  ASSERT_FALSE(r.err.empty()) << report(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line\n" << report(r);
  EXPECT_EQ(r.err.back(), '\n') << report(r);
  EXPECT_TRUE(has(r.err, "--batch")) << report(r);
  EXPECT_FALSE(has(r.out, "loaded")) << report(r);
}

}  // namespace
