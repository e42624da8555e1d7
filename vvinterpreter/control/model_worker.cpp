#include "control/model_worker.hpp"

#include "runner/fault_guard.hpp"

namespace vvi {

model_worker::model_worker() : thread_([this] { loop(); }) {}

model_worker::~model_worker() {
  {
    std::lock_guard<std::mutex> lock(m_);
    quit_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void model_worker::submit(std::function<void()> job, const std::string& what) {
  {
    std::lock_guard<std::mutex> lock(m_);
    job_ = std::move(job);
    what_ = what;
    busy_ = true;
    since_ = std::chrono::steady_clock::now();
  }
  wake_.notify_all();
}

bool model_worker::busy() const {
  std::lock_guard<std::mutex> lock(m_);
  return busy_;
}

double model_worker::busy_seconds() const {
  std::lock_guard<std::mutex> lock(m_);
  return busy_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - since_).count() : 0;
}

std::string model_worker::what() const {
  std::lock_guard<std::mutex> lock(m_);
  return what_;
}

bool model_worker::take_finished() {
  std::lock_guard<std::mutex> lock(m_);
  bool f = finished_;
  finished_ = false;
  return f;
}

void model_worker::loop() {
  fault_guard::prepare_thread();  // a stack overflow in a step is reported too
  std::unique_lock<std::mutex> lock(m_);
  for (;;) {
    wake_.wait(lock, [this] { return quit_ || job_; });
    if (quit_) return;
    std::function<void()> job = std::move(job_);
    job_ = nullptr;
    lock.unlock();
    job();  // never throws: the runner reports errors as values
    lock.lock();
    busy_ = false;
    finished_ = true;
    lock.unlock();
    job_ended_();
    lock.lock();
  }
}

}  // namespace vvi
