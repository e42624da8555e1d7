// The runs of a sweep, J at a time, each a process of its own
// (experiment/child_process.hpp). SIGINT, SIGTERM and SIGHUP to the sweep
// start no more runs and end the running ones (they remove what they were
// writing; being unfinished, they run again next time).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace vvi {

struct queued_run {
  unsigned number = 0;
  std::vector<std::string> command;
  std::string folder;  //!< where it runs; its output goes to stdout.txt and stderr.txt there
};

struct run_end {
  unsigned number = 0;
  int wait_status = 0;      //!< as waitpid gives it
  std::string start_error;  //!< it could not start: why
  bool interrupted = false; //!< ended by the sweep's interruption: neither finished nor failed
  double seconds = 0;
};

//! The files a run's standard output and error go to, in its folder.
inline constexpr const char* run_output_file = "stdout.txt";
inline constexpr const char* run_error_file = "stderr.txt";

//! The cores this process may use (its CPU affinity: a Slurm or cgroup
//! allocation, taskset), at least 1: the default of --jobs.
unsigned usable_cores();

//! Runs `runs` in order, `jobs` at a time; `ended` is told of each run as
//! it ends, `tick` about twice a second (progress). Returns 0, or the
//! signal that interrupted the sweep.
int run_all(const std::vector<queued_run>& runs, unsigned jobs, const std::function<void(const run_end&)>& ended,
            const std::function<void()>& tick);

}  // namespace vvi
