// The command line of experiments (DESIGN.md, "Command-line contracts"):
// --sweep, --seeds, --jobs, --shard, --out, --merge and --slurm. They are
// registered in one block (add_sweep_options) beside the host's other
// options; each value is checked as it is read, and what the options say
// together in check_sweep_options.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace vvi {

struct sweep_options {
  std::vector<std::string> sweeps;  //!< --sweep NAME=V1,V2,... or NAME=LO:HI:COUNT, as typed
  unsigned seeds = 0;               //!< --seeds K (0: not given; the runs use --seed)
  unsigned jobs = 0;                //!< --jobs J (0: not given; the cores this process may use)
  unsigned shard = 0, shards = 0;   //!< --shard I/N (0/0: not given)
  std::string out;                  //!< --out DIR
  std::vector<std::string> merge;   //!< --merge DIR [DIR ...]
  unsigned slurm = 0;               //!< --slurm N: a Slurm job array of N shards (0: not given)

  //! A sweep runs (--sweep or --seeds).
  bool sweeping() const { return !sweeps.empty() || seeds > 0; }
  bool merging() const { return !merge.empty(); }
};

//! Registers the options above; a value that cannot be taken throws
//! CLI::ValidationError with the reason.
void add_sweep_options(CLI::App& app, sweep_options& s);

//! What the options say together, given the host's other choices: "" or
//! the reason they cannot be used so. `model_given`: a MODEL was named.
std::string check_sweep_options(const sweep_options& s, bool model_given);

}  // namespace vvi
