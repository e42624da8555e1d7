// What the model controller sees of the window: the scene (scene_view),
// the messages on the panel and the terminal, the pictures to take on the
// next frames (screenshots, recorded frames), the watch on the model's
// files, and the state record sent to the supervisor.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "control/controller_view.hpp"
#include "series/movie.hpp"
#include "viewer/build_watch.hpp"
#include "viewer/scene_view.hpp"

namespace vvi {

class model_controller;

//! A picture of the scene to take: a file, or a movie's frame of a step.
struct scene_shot {
  std::string path;
  unsigned long step = 0;
};

class window_view : public controller_view, public messages {
 public:
  window_view(const options& o, const state_record& from);
  //! The controller this view serves (made after the view).
  void attach(model_controller& c) { controller_ = &c; }

  // ---- controller_view ----
  bool caught_up() const override;
  void model_changed(const model_change& c) override;
  bool view(const command& c) override;
  void say(const std::string& m) override;
  void show_error(const std::string& shown, const std::string& line) override;
  void clear_error() override { error_.clear(); }
  void record_changed(const state_record& r) override;
  void abandon_job() override;
  void build_started() override { watch_.build_started(); }
  void compiling() override;
  void build_finished(const build_result& b) override { watch_.build_finished(b); }
  std::string record_picture(const std::string& file, unsigned long step) override;
  std::string end_movie(const std::string& file, bool keep) override;

  // ---- for the frame ----
  scene_view& scene() { return scene_; }
  build_watch& watch() { return watch_; }
  //! A frame was drawn; `idle`: without the model's code running.
  void drawn(bool idle) { drawn_since_job_ = drawn_since_job_ || idle; }
  //! The picture of the scene (without the panel) is wanted now: the
  //! files to write it to (pictures, movies' frames). Taken once.
  std::vector<scene_shot> take_scene_shots();
  //! The picture of the whole window is wanted: its path ("" : none). Taken once.
  std::string take_window_shot();
  //! Writes a picture of the current GL frame (a .mp4: a frame of the movie).
  void save_picture(const scene_shot& shot, int w, int h);
  //! The pictures taken: the movies whose recording ended are put in place.
  void pictures_taken();
  //! The next free vv_screenshot_NNN.png, and vv_session_NNN.vvs.
  std::string next_screenshot_name();
  std::string next_session_name();
  //! The next free vv_checkpoint_NNN.ckpt; the last one given.
  std::string next_checkpoint_name();
  const std::string& last_checkpoint_name() const { return last_checkpoint_; }
  bool quit_asked() const { return quit_; }
  //! The window's part of the record (camera, display, screenshots).
  view_record record(const int window[4]) const;

  const std::string& error() const { return error_; }
  const std::string& message() const { return message_; }

 private:
  const options& o_;
  model_controller* controller_ = nullptr;
  scene_view scene_;
  build_watch watch_;
  std::string message_, error_;
  bool drawn_since_job_ = true;
  bool frame_wanted_ = false;  // proxy.record_frame, after a step
  std::string shot_path_, window_shot_path_;
  std::vector<scene_shot> series_shots_;  // of recorded series, for the next frame
  std::map<std::string, std::unique_ptr<movie_writer>> movies_;
  std::map<std::string, bool> movies_ending_;  // once their last frames are taken: keep them?
  int screenshots_ = 0;
  std::string last_checkpoint_;
  bool quit_ = false;
};

}  // namespace vvi
