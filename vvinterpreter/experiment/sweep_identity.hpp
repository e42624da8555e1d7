// What makes two sweeps the same sweep: the program (a hash of the .vvp
// and the headers it includes, not of its path), the swept parameters and
// their values, the seeds, and the batch options that decide the results.
// It is written to DIR/sweep.txt, one item a line: a sweep resumes only in
// a folder of the same sweep, and --merge joins only folders of one sweep
// (and rebuilds the plan from it).
//
//   vv sweep 1
//   program 5f0c...           content hash of the program's sources
//   plots plots.csv           each run's plots file
//   parameter rate 0,0.5,1    one line per --sweep, in order
//   seeds 3                   seeds 1..3 (or "seed 7": --seed 7, no --seeds)
//   option --steps            the batch options, one token a line
//   option 10
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "experiment/sweep_plan.hpp"

namespace vvi {

struct sweep_identity {
  std::string program;  //!< content hash
  std::string plots;
  std::vector<swept_parameter> parameters;
  unsigned seeds = 0;      //!< K of --seeds, or 0
  std::uint64_t seed = 0;  //!< --seed when seeds is 0
  std::vector<std::string> options;

  std::string text() const;
  sweep_plan plan() const { return sweep_plan(parameters, seeds, seed); }
};

//! The file in a sweep's folder.
inline constexpr const char* identity_file = "sweep.txt";

//! Reads DIR/sweep.txt's text; std::nullopt (with `why`) when it is not one.
std::optional<sweep_identity> parse_identity(const std::string& text, std::string& why);

//! The content hash of a program's source files (order does not matter).
std::string program_hash(const std::vector<std::string>& source_files);

//! The first line where two identities' texts differ, as
//! "\"parameter rate 1,2\" there, \"parameter rate 1,2,3\" here".
std::string first_difference(const std::string& there, const std::string& here);

}  // namespace vvi
