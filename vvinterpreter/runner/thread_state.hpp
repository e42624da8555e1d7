// Whether a thread of a supervised child may be asked where it is (a
// stack sample) without changing what the model does.
#pragma once

#include <sys/types.h>

namespace vvi {

//! The thread runs, or waits in a system call that the kernel restarts
//! after a signal handler (SA_RESTART), not one a signal cuts short (a
//! sleep, a poll: the model would see them end early).
bool safe_to_sample(pid_t pid, pid_t thread);

}  // namespace vvi
