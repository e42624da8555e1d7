// The process that stays up while a model's code runs in a child process.
// It reads the child's report pipe (runner/fault_guard.hpp): what the model
// is doing, the modules it loaded, the files it is writing, free-form lines
// (the viewer's state), and the crash report if it dies. It ends an
// activity that runs past its time limit, tells about one that runs long,
// notices a child that was stopped (SIGSTOP, a terminal stop), and asks the
// child where it is (a stack sample) before it ends it, so every report can
// name a .vvp line. An OOM kill or any other death is noticed too.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vvi {

//! Where a thread of the child was: code addresses and the mapped files to
//! look them up in.
struct stack_sample {
  std::string why;         //!< "running" (asked for), "exit" (exit() was called), "idle"
  std::uintptr_t pc = 0;   //!< the interrupted instruction (0: every frame is a return address)
  std::vector<std::uintptr_t> frames;
  std::vector<std::string> maps;  //!< /proc/PID/maps lines of mapped files
};

//! What the child's report said when it died of a signal.
struct crash_info : stack_sample {
  std::string signal;      //!< "SIGSEGV", ...; empty when it died without a report
  std::string exception;   //!< what an uncaught exception said
};

//! What the child was doing (its last announced activity).
struct child_activity {
  std::string what;   //!< "step", "start", "loading", ...; empty when idle
  unsigned step = 0;
};

struct child_end {
  //! interrupted: this process got SIGTERM, SIGINT or SIGHUP (in `signal`)
  //! and ended the child. stopped: the child was stopped (SIGSTOP, SIGTSTP,
  //! SIGTTIN, SIGTTOU: in `signal`) while this process ran, and was ended.
  enum kind_t { exited, crashed, timed_out, interrupted, stopped } kind = exited;
  int exit_code = 0;       //!< exited
  int signal = 0;          //!< crashed, interrupted, stopped: the signal
  crash_info crash;        //!< crashed
  //! The running activity's stack, when the child was asked (timed_out,
  //! stopped, a Stop in the viewer) or called exit() inside a block.
  stack_sample sample;
  child_activity activity; //!< at the end; not empty after `exited`: it exited inside a block
  double activity_seconds = 0;  //!< how long it had run (timed_out)
  double time_limit = 0;        //!< the limit it ran past (timed_out)
  //! Files the child was writing when it ended (target → temporary); the
  //! temporaries have been removed.
  std::vector<std::pair<std::string, std::string>> writing;
  //! Folders the child made temporaries in (or was about to): after it
  //! ended, what it left there is removed too (a kill between making a
  //! temporary and saying its name).
  std::vector<std::string> writing_folders;
  //! Kills by the kernel's out-of-memory killer while the child ran (-1:
  //! the system does not say).
  long oom_kills = -1;
  //! Copies of plugins the child loaded → the files they came from.
  std::map<std::string, std::string> modules;
};

//! A long activity's state, given to supervision::on_long_activity.
struct long_activity {
  child_activity activity;
  double seconds = 0;
  const stack_sample* sample = nullptr;  //!< where it is (nullptr: no answer)
  //! It waits in a system call that a signal would cut short (a sleep, a
  //! poll), so it was not asked where it is.
  bool waiting = false;
  const std::map<std::string, std::string>* modules = nullptr;
};

//! Seconds from the environment variable `name` (a positive number), or
//! `fallback`: lets tests shorten the waits below.
double seconds_from_environment(const char* name, double fallback);

struct supervision {
  double activity_timeout = 0;  //!< seconds an announced activity may run (0: no limit)
  //! Seconds the close block may run when activity_timeout is 0: closing
  //! (batch's end, the viewer's quit) never waits for ever. 10, or
  //! $VV_CLOSE_TIMEOUT.
  double close_timeout = seconds_from_environment("VV_CLOSE_TIMEOUT", 10);
  //! After this many seconds of one activity (0: never), on_long_activity
  //! is told, and again after twice as long, and so on.
  double notice_after = 0;
  std::function<void(const long_activity&)> on_long_activity;
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
