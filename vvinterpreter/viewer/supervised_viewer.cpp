// The viewer's supervisor: starts the window process, keeps the state
// record it sends, and after a crash or a Stop starts it again from there.
#include <chrono>
#include <cstdio>

#include "control/restart.hpp"
#include "runner/crash_report.hpp"
#include "runner/supervisor.hpp"
#include "viewer/viewer.hpp"

namespace vvi {

namespace {

void say_error(const std::string& text) {
  std::fprintf(stderr, "vvinterpreter: %s\n", text.c_str());
  std::fflush(stderr);
}

}  // namespace

int run_viewer(const options& o) {
  using clock = std::chrono::steady_clock;
  state_record record;
  record.view.color_by = o.color_by;
  std::vector<clock::time_point> restarts;
  for (;;) {
    state_record heard = record;  // if it dies before saying more
    heard.up = heard.quitting = false;
    supervision s;
    s.on_line = [&](const std::string& line) { read_record_line(line, heard); };
    child_end end = run_supervised([&] { return run_viewer_window(o, record); }, s);
    bool model_exit = ended_by_model_exit(end) && heard.up && !heard.quitting;
    if (end.kind == child_end::exited && end.exit_code != viewer_restart_code && !model_exit) {
      remove_module_copies(end);
      return end.exit_code;
    }
    if (end.kind == child_end::interrupted) {  // SIGTERM, Ctrl-C: the window is gone
      remove_module_copies(end);
      return 128 + end.signal;
    }
    if (!heard.up || heard.quitting) {  // nothing to go back to
      crash_text t = describe_crash(end, o.model);
      const char* how = !heard.up ? "the viewer could not start: "
                        : end.kind == child_end::timed_out ? "the viewer could not close: "
                                                           : "the viewer crashed while closing: ";
      say_error(how + t.line);
      remove_module_copies(end);
      return 1;
    }
    // A fault in the viewer's own code would bring it down again at once:
    // give up rather than flicker for ever.
    restarts.push_back(clock::now());
    if (restarts.size() >= 5 && clock::now() - restarts[restarts.size() - 5] < std::chrono::seconds(10)) {
      say_error("the viewer crashed 5 times within 10 s; giving up");
      remove_module_copies(end);
      return 1;
    }
    restart next = restart_after(o, heard, end);
    std::fputs(next.report.c_str(), stderr);
    std::fflush(stderr);
    record = next.record;
    remove_module_copies(end);
  }
}

}  // namespace vvi
