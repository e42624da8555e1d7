// The cores a new model's build counts as idle: those this process may
// use (its CPU affinity: a Slurm allocation, a container's cpuset) that
// the load average leaves free, at least 1, and at most $VV_BUILD_CORES
// when that is set. A new model's declarations' part is compiled beside
// its program only with a second idle core to do it on: on a busy machine
// (a test suite, other runs) compiling the model whole costs a third less.
// (An edit's part, or the viewer's, is compiled beside the program
// whatever this says: it is wanted for the edits.)
#pragma once

namespace vvi {

//! The idle cores, at most `limit` (0: no limit).
unsigned idle_cores_for_a_build(unsigned limit);

}  // namespace vvi
