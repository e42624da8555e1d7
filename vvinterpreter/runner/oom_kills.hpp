// Whether the kernel's out-of-memory killer was at work: a model that dies
// of SIGKILL without a word was killed from outside, and the report should
// say by whom only when the system says so.
#pragma once

namespace vvi {

//! The number of processes the kernel's out-of-memory killer has killed,
//! as this process's cgroup (v2 memory.events, v1 memory.oom_control) and
//! the whole system (/proc/vmstat) count them, added up: it grows whenever
//! any of them grows. -1 when none of them can be read.
long oom_kill_count();

}  // namespace vvi
