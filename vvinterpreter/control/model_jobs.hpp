// Where the model's code runs for the controller: one job at a time, on a
// thread of its own in the viewer (model_worker.hpp: the window keeps
// drawing and answering while a step runs), or at once on the calling
// thread (batch, the controller's tests).
#pragma once

#include <functional>
#include <string>

namespace vvi {

class model_jobs {
 public:
  virtual ~model_jobs() = default;
  //! Starts a job; there must be none running. `what` says what it does
  //! ("step 3") for the window to show.
  virtual void submit(std::function<void()> job, const std::string& what) = 0;
  virtual bool busy() const = 0;
  //! How long the running job has run.
  virtual double busy_seconds() const = 0;
  virtual std::string what() const = 0;
  //! True once after each job ended.
  virtual bool take_finished() = 0;
};

//! Runs each job at once, on the caller's thread.
class inline_jobs : public model_jobs {
 public:
  void submit(std::function<void()> job, const std::string& what) override {
    what_ = what;
    job();
    finished_ = true;
  }
  bool busy() const override { return false; }
  double busy_seconds() const override { return 0; }
  std::string what() const override { return what_; }
  bool take_finished() override {
    bool f = finished_;
    finished_ = false;
    return f;
  }

 private:
  std::string what_;
  bool finished_ = false;
};

}  // namespace vvi
