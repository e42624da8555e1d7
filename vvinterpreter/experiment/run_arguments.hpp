// The command line of each run of a sweep: the host's own batch mode (its
// crash containment, its messages), given the sweep's command line minus
// the sweep's options, plus the run's --set and --seed. Each run works in
// its own folder, so the outputs the batch options name (--export,
// --screenshot, --plots, frames) land there; the inputs that are paths
// relative to where the sweep was started (the model, the cache) are made
// absolute.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vvi {

struct run_arguments {
  //! The batch options, as typed, in order: the sweep's command line
  //! without the sweep's own options, --batch, --rebuild, --cache and
  //! --seed, and without the model.
  std::vector<std::string> batch_options;
  std::string model;      //!< absolute
  std::string cache;      //!< absolute
  std::string plots;      //!< the run's plots file, in its folder (--plots, else plots.csv)
  bool plots_given = false;  //!< --plots is among batch_options
};

//! Splits the sweep's command line (argv[1..]); `model` and `cache` as the
//! options read them.
run_arguments arguments_of_runs(int argc, const char* const* argv, const std::string& model, const std::string& cache,
                                const std::string& plots);

//! The batch options that decide a run's results (for the sweep's
//! identity): batch_options without --quiet.
std::vector<std::string> options_deciding_results(const run_arguments& a);

//! The whole command of one run, from the interpreter `self`.
std::vector<std::string> run_command(const std::string& self, const run_arguments& a,
                                     const std::vector<std::pair<std::string, std::string>>& settings,
                                     std::uint64_t seed);

}  // namespace vvi
