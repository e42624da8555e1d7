// A crashed or stopped model, told in the modeller's terms: the .vvp line
// where it happened, the step, and the model's call stack as .vvp lines
// (read from the plugin's line tables with addr2line).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "runner/supervisor.hpp"

namespace vvi {

struct source_frame {
  std::string function;  //!< "the step block", "f(int)", ...
  std::string file;      //!< as the line table names it (the .vvp path)
  unsigned line = 0;
};

//! The frames of a crash from the innermost out, the model's .vvp frames
//! only (frames of vvlib, the C++ library and the host are left out).
std::vector<source_frame> model_stack(const child_end& end);
//! The same for a stack sample of a running child.
std::vector<source_frame> model_stack(const stack_sample& sample, const std::map<std::string, std::string>& modules);

//! The model's .vvp frames at these code addresses (calls, not return
//! addresses), given the process's /proc/PID/maps lines and the loaded
//! copies of plugins → the files they came from.
std::vector<source_frame> model_frames(const std::vector<std::uintptr_t>& code_addresses,
                                       const std::vector<std::string>& maps_lines,
                                       const std::map<std::string, std::string>& modules);

//! "in step 3", "in start", "while loading the model (a global initialiser)".
std::string activity_phrase(const child_activity& a);
//! "step 3", "the close block", "loading the model (its global initialisers)".
std::string activity_name(const child_activity& a);

struct crash_text {
  std::string line;   //!< one line: "model.vvp:20: crashed with SIGSEGV in step 2"
  std::string panel;  //!< the viewer's wording: "model.vvp:20: crashed (SIGSEGV) in step 2"
  std::string stack;  //!< "  model.vvp:20 in the step block\n..." (may be empty)
};

//! The report of a child that ended before its time: one that died of a
//! signal ("crashed with SIGSEGV", "killed by SIGKILL" saying whether the
//! out-of-memory killer was at work), or any of the kinds below. `model`
//! names the .vvp when no frame of it could be found.
crash_text describe_crash(const child_end& end, const std::string& model);

//! "model.vvp:22: step 3 ran longer than 2 s and was ended", at the line
//! where it was.
crash_text describe_timeout(const child_end& end, const std::string& model);

//! "model.vvp:8: stopped by SIGSTOP in step 1 (why that happens), and ended".
crash_text describe_stop(const child_end& end, const std::string& model);

//! A child that exited inside a block (end.activity is not empty):
//! "model.vvp:8: the model called exit(0) in step 1, before the run was done".
crash_text describe_exit(const child_end& end, const std::string& model);

//! "model.vvp:22: step 2 has been running for 10 s; --step-timeout ...";
//! limit: the --step-timeout, or 0.
std::string describe_long_activity(const long_activity& a, const std::string& model, double limit);

//! Where the running activity was when the child last sent its stack
//! ("model.vvp:22"), or `model`: the viewer's Stop.
std::string stopped_place(const child_end& end, const std::string& model);

}  // namespace vvi
