// Tells at once when a watched file is saved, so that the viewer looks at
// its files then instead of at its next quarter-second look (file_watch,
// which stays: it alone decides what changed, and it works where this
// cannot). Linux inotify on the files' folders, as editors save by
// renaming a new file over the old one; a listening thread wakes the
// window's loop through `saved`.
//
// Without inotify (no watches left, a file system that has none) it tells
// nothing, and the periodic look is as before.
#pragma once

#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "control/wake_signal.hpp"

namespace vvi {

class file_events {
 public:
  file_events();
  ~file_events();
  file_events(const file_events&) = delete;
  file_events& operator=(const file_events&) = delete;

  //! Listens for these files from now on (instead of the ones before).
  void watch(const std::vector<std::string>& paths);
  //! Whether a watched file was written, renamed into place or removed
  //! since the last call.
  bool take() { return saved_since_.exchange(false); }
  //! Whether take() would say so, without taking it.
  bool pending() const { return saved_since_; }
  //! Called from the listening thread for each such event.
  wake_signal& saved() { return saved_; }

 private:
  void listen();

  int inotify_ = -1;
  int stop_ = -1;  // an eventfd: written to end the thread
  std::mutex m_;
  std::map<int, std::string> folders_;                  // watch descriptor -> folder
  std::set<std::pair<std::string, std::string>> files_;  // (folder, name)
  std::atomic<bool> saved_since_{false};
  wake_signal saved_;
  std::thread listener_;
};

}  // namespace vvi
