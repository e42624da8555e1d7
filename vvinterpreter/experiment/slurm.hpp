// A sweep on a Slurm cluster (--slurm N): a job array of N tasks, each
// running one shard (--shard $SLURM_ARRAY_TASK_ID/N) into DIR/shards/I,
// then a job that waits for the whole array and merges the shards into
// DIR. Both scripts are written to DIR/slurm/; they are submitted with
// sbatch when it is on the PATH, else printed with the commands that
// submit them. sbatch's own environment (SBATCH_PARTITION,
// SBATCH_TIMELIMIT, SBATCH_ACCOUNT, ...) applies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "experiment/run_arguments.hpp"
#include "experiment/sweep_options.hpp"

namespace vvi {

struct slurm_job {
  std::string self;     //!< the interpreter, absolute
  run_arguments args;   //!< the runs' batch options, model and cache
  sweep_options sweep;  //!< --sweep, --seeds, --jobs, --slurm N, --out
  std::uint64_t seed = 0;  //!< --seed, when there is no --seeds
  std::string model;    //!< as typed (the job's name)
};

//! The job array's script (DIR/slurm/sweep.sbatch).
std::string array_script(const slurm_job& j);
//! The merge job's script (DIR/slurm/merge.sbatch).
std::string merge_script(const slurm_job& j);
//! A word for the shell: quoted so that it stays one word, as it is.
std::string shell_word(const std::string& s);

//! Writes both scripts and submits them (or prints them): the exit status.
int submit_to_slurm(const slurm_job& j, bool quiet);

}  // namespace vvi
