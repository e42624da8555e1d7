// Running a program (the compiler) and collecting what it prints.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct process_result {
  int status = -1;     // exit status; -1 if it could not start or was killed
  std::string output;  // standard output and standard error, interleaved
};

//! `niceness`: added to the child's nice value (a build that may wait for
//! others, 0: as this process).
process_result run_process(const std::vector<std::string>& argv, int niceness = 0);

//! The words of a command joined by spaces, as a build's `command` file and
//! the cache's keys record it.
std::string command_line(const std::vector<std::string>& argv);

}  // namespace vvi
