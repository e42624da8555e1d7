// Runs the model's code on a thread of its own, one job at a time, so a
// step that takes long (or never ends) leaves the window drawing and
// answering. While a job runs the window must not call into the model (no
// render blocks, no meshes): it draws what it kept from before.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "control/model_jobs.hpp"
#include "control/wake_signal.hpp"

namespace vvi {

class model_worker : public model_jobs {
 public:
  model_worker();
  ~model_worker();
  model_worker(const model_worker&) = delete;
  model_worker& operator=(const model_worker&) = delete;

  void submit(std::function<void()> job, const std::string& what) override;
  bool busy() const override;
  double busy_seconds() const override;
  std::string what() const override;
  bool take_finished() override;
  //! Called when a job ends.
  wake_signal& job_ended() { return job_ended_; }

 private:
  void loop();

  mutable std::mutex m_;
  std::condition_variable wake_;
  std::function<void()> job_;
  std::string what_;
  bool busy_ = false, finished_ = false, quit_ = false;
  std::chrono::steady_clock::time_point since_;
  wake_signal job_ended_;  // before the thread, which calls it
  std::thread thread_;
};

}  // namespace vvi
