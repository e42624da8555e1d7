// Wakes the window's event loop from another thread when a job or a build
// ends, so the loop can sleep until then instead of drawing frames to
// notice it (a frame drawn in software takes a core from the compiler).
#pragma once

#include <atomic>
#include <functional>
#include <mutex>

namespace vvi {

class wake_signal {
 public:
  //! What waking does (posting an empty event to the window), or nothing.
  //! Once disconnected it is never called again.
  void connect(std::function<void()> wake) {
    std::lock_guard<std::mutex> lock(m_);
    wake_ = std::move(wake);
  }
  void disconnect() { connect(nullptr); }
  //! From any thread.
  void operator()() {
    ++times_;
    std::lock_guard<std::mutex> lock(m_);
    if (wake_) wake_();
  }
  //! How often it was called: the loop compares it with the ends it has
  //! seen, as it may wake a moment before the result it signals is there.
  unsigned long times() const { return times_; }

 private:
  std::mutex m_;
  std::function<void()> wake_;
  std::atomic<unsigned long> times_{0};
};

}  // namespace vvi
