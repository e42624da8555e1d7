// Inside the process that runs a model's code: a fatal signal (a crash, a
// stack overflow, abort, an exception nobody catches) becomes a report on a
// pipe to the supervising process, written after what the model printed has
// been flushed. The process then dies as it would have; the supervisor
// (runner/supervisor.hpp) turns the report into .vvp lines and decides what
// happens next. Nothing here tries to recover in-process.
//
// The same pipe carries what the model is doing ("begin step 3"), so the
// supervisor can time a step, the modules loaded (to name their lines), the
// files being written (removed if the process dies), and, when the
// supervisor asks with sample_signal(), where the running block is: the
// stack of the thread that runs it, without stopping it. A model that calls
// exit() inside a block reports its stack the same way.
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
//! supervisor, which times announced activities (--step-timeout, Stop) and
//! may ask for their stack.
void begin(const char* what, unsigned step = 0, bool announce = true);
//! The activity ended normally.
void finish(bool announce = true);

//! The signal the supervisor sends to ask where the announced activity is:
//! the thread that runs it answers with a "sample" report of its stack.
//! Queued (sigqueue) with sample_request(number, last): the answer carries
//! the number; the last before the process is ended flushes what the model
//! printed first, and the model goes no further.
int sample_signal();
constexpr int sample_request(int number, bool last) { return number * 2 + (last ? 1 : 0); }

//! Sends the stack of the announced activity's thread to the supervisor
//! now (from any thread of this process) and waits for it to be sent, at
//! most max_seconds; false when nothing runs or no answer came.
bool report_activity_stack(double max_seconds = 0.5);

//! Tells the supervisor that `loaded` (as it appears in /proc/self/maps) is
//! a copy of `original`, whose line tables name the .vvp lines.
void note_module(const std::string& loaded, const std::string& original);

//! A temporary file is being written for `target` (runner/output_file.hpp):
//! if this process dies before note_written, the temporary goes (here on
//! SIGTERM, SIGINT and SIGHUP; by the supervisor on anything else).
void note_writing(const std::string& temporary, const std::string& target);
//! Said before the temporary is made in `folder`: if this process is killed
//! before note_writing, the supervisor still finds what it left there.
void note_writing_in(const std::string& folder);
void note_written(const std::string& temporary);

//! Sends one line of free text to the supervisor (the viewer's state).
void send(const std::string& line);

//! The report pipe, or -1.
int report_fd();

}  // namespace vvi::fault_guard
