// --script: commands the viewer runs in its live window, one per line, so
// the interactive viewer can be driven (and tested) without a person.
//
//   step N | run | rewind | end | reread | recompile | fit
//   screenshot FILE.png | window-screenshot FILE.png (with the panel)
//   export MESH FILE | rotate DX DY | zoom F | wait MS | stop | quit
//   pick LABEL | set NAME=VALUE | save-params | color-by NAME|none
//   show faces|edges|points|flat|back-faces|auto-fit on|off | plots FILE.csv
//   (script_help describes each one; --help prints it)
//
// Each command waits for the one before to finish (a step, a build),
// except `wait` and `window-screenshot`, which go on beside a running step,
// and `stop`: it ends a step that has run for half a second (as the Stop
// button does: the model restarts at its last good state).
//
// Blank lines are skipped; a # that starts a word starts a comment, on a
// line of its own or after a command.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct script_command {
  enum kind_t {
    step, run, rewind, end, reread, recompile, fit, screenshot, window_screenshot, export_mesh, rotate, zoom, wait, stop,
    quit, pick, set, save_params, color_by, show, plots
  };
  kind_t kind = step;
  long count = 1;        // step N, wait MS
  double a = 0, b = 0;   // rotate DX DY (degrees), zoom F
  std::string path;      // screenshot, export
  std::string mesh;      // export
  std::string name, value;  // set NAME=VALUE, color-by NAME, show WHAT on|off
  int line = 0;
};

//! Every command with its arguments and what it does, a line each.
extern const char* const script_help;

//! The commands of a script; on a bad line, nothing and error =
//! "file:line: problem".
std::vector<script_command> parse_script(const std::string& text, const std::string& name, std::string& error);

}  // namespace vvi
