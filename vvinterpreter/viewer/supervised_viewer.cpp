// The viewer's supervisor: starts the window process, listens to its state,
// and after a crash or a Stop starts it again from where it was.
#include <chrono>
#include <cstdio>

#include "runner/crash_report.hpp"
#include "runner/supervisor.hpp"
#include "viewer/viewer.hpp"

namespace vvi {

namespace {

std::string restart_note(const viewer_resume& r) {
  if (r.good_plugin.empty()) return "restarted; no model had loaded yet";
  if (r.replay) return "restarted; the model was run again to step " + std::to_string(r.good_steps) + ", its last good state";
  return "restarted at step 0 (running again to the last step is off)";
}

void say_error(const std::string& text) {
  std::fprintf(stderr, "vvinterpreter: %s\n", text.c_str());
  std::fflush(stderr);
}

viewer_resume resume_after(const options& o, const viewer_resume& before, const viewer_state& state,
                           const child_end& end) {
  viewer_resume r;
  r.restarted = true;
  r.camera = state.camera;
  for (int i = 0; i < 4; ++i) r.window[i] = state.window[i];
  r.script_pos = state.script_pos;
  r.screenshots = state.screenshots;
  r.replay = state.replay;
  r.good_plugin = state.model_plugin;
  r.good_steps = state.model_steps;
  r.bad_plugin = before.bad_plugin;
  r.no_render_plugin = before.no_render_plugin;
  bool stopped = end.kind == child_end::exited;
  std::string what = stopped ? state.stopped_activity : end.activity.what;
  // A new build that failed on its way in: the last good model comes back.
  if (!state.trying_plugin.empty() && (what == "loading" || what == "start" || what == "step"))
    r.bad_plugin = state.trying_plugin;
  if (what.rfind("render", 0) == 0) r.no_render_plugin = state.model_plugin;
  if (!r.replay) r.good_steps = 0;
  r.note = restart_note(r);
  if (stopped) {
    r.error = stopped_place(end, o.model) + ": " + state.stopped + "; " + r.note;
    say_error(r.error);
  } else {
    crash_text t = describe_crash(end, o.model);
    std::fprintf(stderr, "vvinterpreter: %s\n%s", t.line.c_str(), t.stack.c_str());
    std::fflush(stderr);
    r.error = t.panel + (t.stack.empty() ? "" : "\n" + t.stack);
  }
  return r;
}

}  // namespace

int run_viewer(const options& o) {
  using clock = std::chrono::steady_clock;
  viewer_resume resume;
  std::vector<clock::time_point> restarts;
  for (;;) {
    viewer_state state;
    state.model_plugin = resume.good_plugin;  // if it dies before saying more
    state.model_steps = resume.good_steps;
    state.camera = resume.camera;
    state.script_pos = resume.script_pos;
    state.screenshots = resume.screenshots;
    state.replay = resume.replay;
    for (int i = 0; i < 4; ++i) state.window[i] = resume.window[i];
    supervision s;
    s.on_line = [&](const std::string& line) { state.hear(line); };
    child_end end = run_supervised([&] { return run_viewer_window(o, resume); }, s);
    if (end.kind == child_end::exited && end.exit_code != viewer_restart_code) {
      remove_module_copies(end);
      return end.exit_code;
    }
    if (end.kind == child_end::interrupted) {  // SIGTERM, Ctrl-C: the window is gone
      remove_module_copies(end);
      return 128 + end.signal;
    }
    if (!state.up || state.quitting) {  // nothing to go back to
      crash_text t = describe_crash(end, o.model);
      const char* how = !state.up ? "the viewer could not start: "
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
    resume = resume_after(o, resume, state, end);
    remove_module_copies(end);
  }
}

}  // namespace vvi
