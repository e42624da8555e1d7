// What batch mode shows of a model: the progress of its steps on a
// terminal, the files it writes, the vertices --pick describes, the
// offscreen screenshot; and its state record, told to the supervisor so a
// crash during --replay names the event it stopped at.
#pragma once

#include <chrono>
#include <string>

#include "app/options.hpp"
#include "control/controller_view.hpp"

namespace vvi {

class model_controller;
class model_runner;

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
  explicit batch_view(const options& o) : o_(o), bar_(o.steps, o.quiet) {}
  void attach(model_controller& c) { controller_ = &c; }
  //! The steps run so far count from here (after a replay).
  void count_steps_from(unsigned step) { first_step_ = step; }

  void model_changed(const model_change& c) override;
  bool view(const command& c) override;
  void wrote(const std::string& path) override;
  void show_error(const std::string&, const std::string& line) override;
  void record_changed(const state_record& r) override;

  //! The first error the view itself met (a pick, a screenshot), or "".
  const std::string& failure() const { return failure_; }

 private:
  const options& o_;
  model_controller* controller_ = nullptr;
  progress bar_;
  unsigned first_step_ = 0;
  std::string failure_;
};

//! The batch screenshot: offscreen, the whole model in view; "" or the error.
std::string batch_screenshot(const options& o, const std::string& path, const model_runner& runner);

}  // namespace vvi
