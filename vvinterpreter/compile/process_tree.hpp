// Stopping a program together with every process it started: a compiler
// driver and the compiler, assembler and linker it runs one after another.
#pragma once

#include <sys/types.h>

namespace vvi {

//! Kills every descendant of `pid`, each stopped first so that it starts
//! no new process meanwhile, then asks `pid` itself to end (SIGTERM: a
//! compiler driver then removes its temporary files, as on Ctrl-C). The
//! caller still reaps `pid`.
void end_process_tree(pid_t pid);

}  // namespace vvi
