// How a run of a sweep ended, kept in its folder (DIR/run-NNNN/). A run
// counts as finished only when its marker `finished` exists: the marker is
// written (atomically) after the run's process ended well, and so after
// all its outputs. A run whose process failed gets the marker `failed`
// instead, holding its reason and .vvp line. A folder with neither (the
// sweep was killed, even with kill -9) is an unfinished run: the next
// sweep runs it again from an empty folder.
#pragma once

#include <string>

namespace vvi {

enum class run_state { unfinished, finished, failed };

struct run_failure {
  std::string line;    //!< "model.vvp:12", or "" when no line is known
  std::string reason;  //!< "crashed with SIGABRT in step 2"
};

//! The state of the run whose folder this is (a missing folder: unfinished).
run_state state_of_run(const std::string& folder);
//! The marker of a finished run; "" or why it could not be written.
std::string mark_finished(const std::string& folder);
//! The marker of a failed run; "" or why it could not be written.
std::string mark_failed(const std::string& folder, const run_failure& f);
//! What a failed run's marker says.
run_failure read_failure(const std::string& folder);

//! The failure of a batch process, from its standard error (its last line
//! "vvinterpreter: WHERE: WHAT", WHERE the .vvp line when there is one)
//! or, without such a line, from how it ended. A path `shown_as_from` at
//! the start of WHERE is shown as `shown_as` (the model as the user typed
//! it, not the absolute path the run was given).
run_failure failure_from_output(const std::string& error_output, const std::string& how_it_ended,
                                const std::string& shown_as_from, const std::string& shown_as);

}  // namespace vvi
