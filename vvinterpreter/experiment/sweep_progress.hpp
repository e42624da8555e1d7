// The sweep's progress on the terminal: runs done, failed and remaining,
// and the time left (from the pace of the runs finished so far). On a
// terminal it is one line, rewritten in place; elsewhere (a log, a Slurm
// output file) a plain line per run that ends.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace vvi {

//! "about 40 s", "about 3 min", "about 1 h 5 min".
std::string time_left_text(double seconds);

class sweep_progress {
 public:
  //! `total`: the runs to run now; `to`: where it is written; `rewrite`:
  //! one line rewritten in place (a terminal) rather than a line per run.
  sweep_progress(std::size_t total, std::FILE* to, bool rewrite);

  //! A run ended: finished or failed; `what` names it ("run 3 (rate=0.5
  //! seed=2)") for the plain lines.
  void ended(bool failed, const std::string& what);
  //! Rewrites the line (the time left goes down).
  void tick();
  //! Ends the rewritten line.
  void finish();

  //! The state in words: "3 done, 1 failed, 8 remaining, about 12 s left".
  std::string state() const;

 private:
  std::size_t total_, done_ = 0, failed_ = 0;
  std::FILE* to_;
  bool rewrite_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace vvi
