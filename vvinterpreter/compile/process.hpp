// Running a program (the compiler) and collecting what it prints.
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace vvi {

struct process_result {
  int status = -1;     // exit status; -1 if it could not start or was killed
  std::string output;  // standard output and standard error, interleaved
  bool cancelled = false;  // stopped because `cancel` was set
};

//! `niceness`: added to the child's nice value (a build that may wait for
//! others, 0: as this process). `cancel`: looked at every tenth of a second
//! while the program runs; once it is set, the program and every process it
//! started are stopped (its own temporary files removed, as on Ctrl-C).
process_result run_process(const std::vector<std::string>& argv, int niceness = 0,
                           const std::atomic<bool>* cancel = nullptr);

//! The words of a command joined by spaces, as a build's `command` file and
//! the cache's keys record it.
std::string command_line(const std::vector<std::string>& argv);

}  // namespace vvi
