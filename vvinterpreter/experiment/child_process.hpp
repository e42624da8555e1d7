// Starting the processes of a sweep (each run is the host's batch mode in
// a process of its own). A child is in a process group of its own, so a
// terminal's Ctrl+C or Ctrl+Z reaches the sweep, which decides; and it is
// killed when the sweep dies, even by kill -9 (PR_SET_PDEATHSIG), so no
// run goes on writing into a folder the next sweep is redoing.
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace vvi {

//! Starts argv[0] (a path) in `folder`, its standard output and error
//! written to the files `out` and `err` (relative to the folder). Returns
//! its pid, or -1 with the reason in `why`.
pid_t start_child(const std::vector<std::string>& argv, const std::string& folder, const std::string& out,
                  const std::string& err, std::string& why);

struct captured {
  int status = -1;       //!< exit status; -1 when it did not start or died of a signal
  std::string out, err;  //!< standard output, standard error
};

//! Runs argv to its end, capturing its output.
captured run_captured(const std::vector<std::string>& argv);

//! "exited with status 3", "killed by SIGKILL", from a wait status.
std::string how_it_ended(int wait_status);

}  // namespace vvi
