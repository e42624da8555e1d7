#include "viewer/window_view.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "control/model_controller.hpp"
#include "render/image.hpp"
#include "runner/fault_guard.hpp"
#include "series/step_names.hpp"

namespace vvi {

window_view::window_view(const options& o, const state_record& from)
    : o_(o), scene_(from.view, *this), watch_(o.model), screenshots_(from.view.screenshots) {
  if (from.restarted) error_ = from.error, message_ = from.note;
}

bool window_view::caught_up() const {
  return drawn_since_job_ && !frame_wanted_ && shot_path_.empty() && window_shot_path_.empty() &&
         series_shots_.empty();
}

void window_view::model_changed(const model_change& c) {
  drawn_since_job_ = false;  // each state a job leaves is drawn (and recorded) once before the next
  watch_.model_files(controller_->facts().file_objects);
  const model_runner& r = controller_->runner();
  scene_.hold_framing(controller_->recording());  // a recording keeps its view
  if (c.kind == model_change::loaded) {
    const std::string& no_render = controller_->record().no_render_plugin;
    scene_.loaded(r, no_render.empty() || no_render != r.plugin_path());
  } else {
    scene_.refresh(r);
  }
  if (c.kind == model_change::stepped && controller_->facts().record_frame) frame_wanted_ = true;
}

bool window_view::view(const command& c) {
  switch (c.kind) {
    case command::screenshot: shot_path_ = c.path; return true;
    case command::window_screenshot: window_shot_path_ = c.path; return true;
    case command::quit: quit_ = true; return true;
    default: return scene_.carry_out(c, controller_->runner(), controller_->busy());
  }
}

void window_view::say(const std::string& m) {
  message_ = m;
  std::printf("%s\n", m.c_str());
  std::fflush(stdout);
}

void window_view::show_error(const std::string& shown, const std::string& line) {
  error_ = shown;
  std::fprintf(stderr, "vvinterpreter: %s\n", line.c_str());
  std::fflush(stderr);
}

void window_view::record_changed(const state_record& r) { fault_guard::send(record_line(r)); }

// Stop: the job cannot be cut short inside this process, so the window
// asks its supervisor to start it again at the last good state.
void window_view::abandon_job() {
  fault_guard::report_activity_stack();  // the supervisor names the line it was stopped at
  std::fflush(nullptr);
  _exit(viewer_restart_code);  // the worker may be anywhere: no clean-up
}

// Said once the sources are read: an edit after this line is one the
// build does not have.
void window_view::compiling() {
  std::printf("compiling %s ...\n", o_.model.c_str());
  std::fflush(stdout);
}

std::string window_view::record_picture(const std::string& file, unsigned long step) {
  scene_.hold_framing(true);
  series_shots_.push_back({file, step});
  return "";
}

std::string window_view::end_movie(const std::string& file, bool keep) {
  movies_ending_[file] = keep;
  if (series_shots_.empty()) pictures_taken();
  return "";
}

void window_view::pictures_taken() {
  for (const auto& [file, keep] : movies_ending_) {
    auto m = movies_.find(file);
    if (m == movies_.end()) continue;
    std::string e = keep ? m->second->finish() : "";
    if (!e.empty()) show_error(e, e);
    else if (keep) say("wrote " + file);
    movies_.erase(m);
  }
  movies_ending_.clear();
  if (!controller_->recording()) scene_.hold_framing(false);
}

std::vector<scene_shot> window_view::take_scene_shots() {
  std::vector<scene_shot> paths;
  if (frame_wanted_ && controller_->facts().loaded) {
    std::error_code ec;
    std::filesystem::create_directories(o_.frames, ec);
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%05u.png", controller_->facts().steps);
    paths.push_back({o_.frames + name});
  }
  frame_wanted_ = false;
  if (!shot_path_.empty()) paths.push_back({shot_path_});
  shot_path_.clear();
  paths.insert(paths.end(), series_shots_.begin(), series_shots_.end());
  series_shots_.clear();
  return paths;
}

std::string window_view::take_window_shot() {
  std::string path = window_shot_path_;
  window_shot_path_.clear();
  return path;
}

void window_view::save_picture(const scene_shot& shot, int w, int h) {
  const std::string& path = shot.path;
  std::string e;
  if (series_file_of(path) == series_file::movie) {
    std::unique_ptr<movie_writer>& movie = movies_[path];
    if (!movie) movie = movie_writer::open(path, w, h, o_.fps, e);
    if (movie) e = movie->add(shot.step, read_pixels(w, h), w, h);
    if (!e.empty()) movies_.erase(path);  // a movie that misses a frame is not written
    if (!e.empty()) show_error(e, e);
    return;
  }
  e = write_png(path, w, h, read_pixels(w, h));
  if (e.empty()) say("wrote " + path);
  else show_error(e, e);
}

std::string window_view::next_screenshot_name() {
  for (;;) {
    char name[40];
    std::snprintf(name, sizeof name, "vv_screenshot_%03d.png", ++screenshots_);
    if (!std::filesystem::exists(name)) return name;
  }
}

std::string window_view::next_session_name() {
  for (int n = 1;; ++n) {
    char name[40];
    std::snprintf(name, sizeof name, "vv_session_%03d.vvs", n);
    if (!std::filesystem::exists(name)) return name;
  }
}

std::string window_view::next_checkpoint_name() {
  for (int n = 1;; ++n) {
    char name[40];
    std::snprintf(name, sizeof name, "vv_checkpoint_%03d.ckpt", n);
    if (!std::filesystem::exists(name)) return last_checkpoint_ = name;
  }
}

view_record window_view::record(const int window[4]) const {
  view_record base;
  for (int i = 0; i < 4; ++i) base.window[i] = window[i];
  base.screenshots = screenshots_;
  return scene_.record(base);
}

}  // namespace vvi
