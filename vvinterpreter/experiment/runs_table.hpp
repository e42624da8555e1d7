// The sweep's tables, assembled from the runs' folders in run order (never
// in the order runs ended), so they are byte-identical for any --jobs and
// after shards are merged.
//
// runs.csv is tidy: a row per finished run and step that recorded a plot,
// "run,seed,<parameters...>,step,<plot series...>". The series are those
// of all finished runs, in the order they first appear (run by run, each
// run's own order); a run that did not record a series at a step has an
// empty cell there.
//
// failed.csv: a row per failed run, "run,seed,<parameters...>,line,reason".
#pragma once

#include <string>

#include "experiment/sweep_plan.hpp"

namespace vvi {

//! runs.csv of the runs in `dir` (DIR/run-NNNN/, each run's plots in the
//! file `plots` there). Throws std::runtime_error naming a finished run's
//! plots file that cannot be read.
std::string runs_csv(const sweep_plan& plan, const std::string& dir, const std::string& plots);

//! failed.csv of the runs in `dir`.
std::string failed_csv(const sweep_plan& plan, const std::string& dir);

}  // namespace vvi
