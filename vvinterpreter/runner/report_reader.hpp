// The supervisor's side of the report pipe (runner/fault_guard.hpp): reads
// the child's lines as they come, one at a time, into the child_end (its
// activity, the modules and files it told of, a crash report, stack
// samples), and passes on lines that are not part of the protocol.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>

#include "runner/supervisor.hpp"

namespace vvi {

class report_reader {
 public:
  using clock_type = std::chrono::steady_clock;

  report_reader(child_end& end, const supervision& s) : end_(end), s_(s) {}

  //! Bytes from the pipe; whole lines are read, the rest kept.
  void feed(const char* data, std::size_t n);

  //! An announced activity runs (begun, not done): it is timed.
  bool busy() const { return timed_; }
  //! When the running activity began (the supervisor moves it on by the
  //! time it was stopped itself).
  clock_type::time_point busy_since;
  //! The number of the last request for a sample; sample_arrived is set
  //! when a whole answer to it has come (the caller clears it).
  int sample_asked = 0;
  bool sample_arrived = false;
  //! Bumped by every "begin": an activity's notices are its own.
  unsigned activity_number = 0;
  //! The thread that runs the activity (its kernel id).
  pid_t activity_thread = 0;

 private:
  void line(const std::string& l);

  child_end& end_;
  const supervision& s_;
  std::string pending_;
  stack_sample* filling_ = nullptr;  // where pc, frame and map lines go
  int sample_number_ = -1;
  bool timed_ = false;
};

}  // namespace vvi
