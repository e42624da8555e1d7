// Experiments: a model run for every combination of parameter values and
// seeds (a sweep), and shards of sweeps joined (merge). See
// docs/experiments.md.
#pragma once

#include "app/options.hpp"

namespace vvi {

//! --sweep / --seeds: the whole sweep (or its shard, or its Slurm jobs);
//! the exit status (0: every run finished; 1: a run failed or the sweep
//! could not run; 2: the options cannot be used so).
int run_sweep(const options& o, int argc, const char* const* argv);

//! --merge DIR... --out DIR.
int run_merge(const options& o);

}  // namespace vvi
