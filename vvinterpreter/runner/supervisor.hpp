// The process that stays up while a model's code runs in a child process.
// It reads the child's report pipe (runner/fault_guard.hpp): what the model
// is doing, the modules it loaded, free-form lines (the viewer's state), and
// the crash report if it dies. It ends an activity that runs past its time
// limit, and an OOM kill or any other death is noticed too.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vvi {

//! What the child's report said when it died of a signal.
struct crash_info {
  std::string signal;      //!< "SIGSEGV", ...; empty when it died without a report
  std::string exception;   //!< what an uncaught exception said
  std::uintptr_t pc = 0;   //!< where the fault happened
  std::vector<std::uintptr_t> frames;
  std::vector<std::string> maps;  //!< /proc/PID/maps lines of mapped files
};

//! What the child was doing (its last announced activity).
struct child_activity {
  std::string what;   //!< "step", "start", "loading", ...; empty when idle
  unsigned step = 0;
};

struct child_end {
  //! interrupted: this process got SIGTERM, SIGINT or SIGHUP (in `signal`)
  //! and ended the child.
  enum kind_t { exited, crashed, timed_out, interrupted } kind = exited;
  int exit_code = 0;       //!< exited
  int signal = 0;          //!< crashed: the signal that ended it
  crash_info crash;        //!< crashed
  child_activity activity; //!< at the end (crashed, timed_out)
  double activity_seconds = 0;
  //! Copies of plugins the child loaded → the files they came from.
  std::map<std::string, std::string> modules;
};

struct supervision {
  double activity_timeout = 0;  //!< seconds an announced activity may run (0: no limit)
  //! Lines that are not part of the protocol (the viewer's own state).
  std::function<void(const std::string&)> on_line;
};

//! Runs child() in a forked process (fault_guard installed, its report going
//! to this process) and waits for it to end. child returns the exit code.
child_end run_supervised(const std::function<int()>& child, const supervision& s);

//! Removes the private copies of plugins a child that died had loaded
//! (runner/plugin.cpp), once its crash has been described.
void remove_module_copies(const child_end& end);

}  // namespace vvi
