// What batch mode shows of a model: the progress of its steps on a
// terminal, the files it writes, the vertices --pick describes, the
// offscreen screenshot; and its state record, told to the supervisor so a
// crash during --replay names the event it stopped at.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "app/options.hpp"
#include "control/controller_view.hpp"
#include "render/camera.hpp"
#include "render/offscreen.hpp"
#include "series/movie.hpp"

namespace vvi {

class model_controller;
class model_runner;
class session;

// "step 12/100, 3.4 s" on one line, only when a person watches standard error.
class progress {
 public:
  progress(unsigned total, bool quiet);
  void update(unsigned done);

 private:
  unsigned total_;
  bool on_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

class batch_view : public controller_view {
 public:
  explicit batch_view(const options& o);
  void attach(model_controller& c) { controller_ = &c; }
  //! The steps run so far count from here (after a replay).
  void count_steps_from(unsigned step) { first_step_ = step; }

  void model_changed(const model_change& c) override;
  bool view(const command& c) override;
  void wrote(const std::string& path) override;
  void show_error(const std::string&, const std::string& line) override;
  void record_changed(const state_record& r) override;
  std::string record_picture(const std::string& file, unsigned long step) override;
  std::string end_movie(const std::string& file, bool keep) override;

  //! From now on the pictures of a series write nothing: they grow the box
  //! that holds the model of every frame (measured()).
  void measure_frame() { measuring_ = true, measured_ = box(); }
  const box& measured() const { return measured_; }
  //! From now on every picture is fitted to this box.
  void use_frame(const box& b) { measuring_ = false, frame_ = b; }

  //! The first error the view itself met (a pick, a screenshot), or "".
  const std::string& failure() const { return failure_; }

 private:
  const options& o_;
  model_controller* controller_ = nullptr;
  progress bar_;
  unsigned first_step_ = 0;
  std::string failure_;
  bool measuring_ = false;
  box measured_;
  std::optional<box> frame_;  // --frame, or the series' measured box
  std::map<std::string, std::unique_ptr<movie_writer>> movies_;
  std::unique_ptr<offscreen> gl_;
  const session* rendering_of_ = nullptr;  // the instance whose render_init ran in gl_

  //! The picture: offscreen, the whole model in view, or the frame when
  //! there is one; RGBA, top row first. "" or the error, about `path`.
  std::string picture(const std::string& path, std::vector<std::uint8_t>& pixels);
};


}  // namespace vvi
