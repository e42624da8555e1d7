// Inside the process that runs a model's code: a fatal signal (a crash, a
// stack overflow, abort, an exception nobody catches) becomes a report on a
// pipe to the supervising process, written after what the model printed has
// been flushed. The process then dies as it would have; the supervisor
// (runner/supervisor.hpp) turns the report into .vvp lines and decides what
// happens next. Nothing here tries to recover in-process.
//
// The same pipe carries what the model is doing ("begin step 3"), so the
// supervisor can time a step, and the modules loaded (to name their lines).
#pragma once

#include <string>

namespace vvi::fault_guard {

//! Installs the handlers for the whole process and an alternate signal
//! stack for the calling thread; reports go to report_fd (-1: none).
void install(int report_fd);

//! An alternate signal stack for a thread that runs model code (a stack
//! overflow must still be reported). Call at the start of the thread.
void prepare_thread();

//! What the model is doing: "loading", "start", "step", "end", "render", ...
//! (step: the step's number, 0 otherwise). announce: also tell the
//! supervisor, which times announced activities (--step-timeout, Stop).
void begin(const char* what, unsigned step = 0, bool announce = true);
//! The activity ended normally.
void finish(bool announce = true);

//! Tells the supervisor that `loaded` (as it appears in /proc/self/maps) is
//! a copy of `original`, whose line tables name the .vvp lines.
void note_module(const std::string& loaded, const std::string& original);

//! Sends one line of free text to the supervisor (the viewer's state).
void send(const std::string& line);

//! The report pipe, or -1.
int report_fd();

}  // namespace vvi::fault_guard
