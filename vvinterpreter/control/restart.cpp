#include "control/restart.hpp"

#include "control/command_text.hpp"
#include "runner/crash_report.hpp"
#include "runner/report_words.hpp"

namespace vvi {

namespace {

// The model's own code, as the report pipe names what it runs (`action
// "Grow"`, `pick of vertex 12`) or a Stop the job it stopped ("action").
bool model_activity(const std::string& what) {
  std::string word = what.substr(0, what.find(' '));
  return word == "loading" || word == "start" || word == "step" || word == "end" || word == "reread" ||
         word == "action" || word == "pick";
}

std::string note_for(const state_record& r) {
  if (r.plugin.empty() || r.plugin == r.bad_plugin) return "restarted; no model had loaded yet";
  if (r.replay)
    return "restarted; the model was run again to step " + std::to_string(r.log.steps()) + ", its last good state";
  return "restarted at step 0 (running again to the last step is off)";
}

}  // namespace

bool ended_by_model_exit(const child_end& end) {
  // The window's own restart leaves by _exit (no handler runs); a model's
  // exit() is seen by the handler, whatever status it gave.
  return end.kind == child_end::exited && model_activity(end.activity.what) &&
         (end.exit_code != viewer_restart_code || end.sample.why == report_words::exit_call);
}

restart restart_after(const options& o, const state_record& last, const child_end& end) {
  restart out;
  state_record& r = out.record;
  r = last;
  r.restarted = true;
  r.up = r.quitting = false;
  r.stopped.clear(), r.stopped_activity.clear();
  r.trying.clear();
  r.replaying = -1;
  // A window that exited asked for a restart after a Stop, or its model
  // ended the process itself inside a block (exit()): a fault like a crash.
  bool model_exit = ended_by_model_exit(end);
  bool stopped = end.kind == child_end::exited && !model_exit;
  std::string what = stopped ? last.stopped_activity : end.activity.what;
  std::string replay_note;
  if (!last.trying.empty()) {
    // A new build that failed on its way in: the last good model comes back.
    if (model_activity(what)) r.bad_plugin = last.trying;
  } else if (last.replaying >= 0 && static_cast<std::size_t>(last.replaying) < last.log.events.size()) {
    // The replay stops at the event it was in (with the steps of it done).
    std::size_t k = static_cast<std::size_t>(last.replaying);
    unsigned long before = last.log.steps_before(k), done = 0;
    if (what == "step" && end.activity.step > before + 1) done = end.activity.step - 1 - before;
    r.log = last.log.up_to(k, done);
    replay_note = "; the replay stopped at event " + std::to_string(k + 1) + " of " +
                  std::to_string(last.log.events.size()) + " (" + command_text(last.log.events[k]) + ")";
  } else if (what == "loading" || what == "start") {
    // The good model itself crashed on its way in (a rewind): not again.
    r.bad_plugin = last.plugin;
  }
  if (what.rfind("render", 0) == 0) r.no_render_plugin = last.plugin;
  if (!r.replay) r.log = event_log{last.log.settings_after(), {}};
  r.note = note_for(r) + replay_note;
  if (stopped) {
    r.error = stopped_place(end, o.model) + ": " + last.stopped + "; " + r.note;
    out.report = "vvinterpreter: " + r.error + "\n";
  } else {
    crash_text t = model_exit ? describe_exit(end, o.model) : describe_crash(end, o.model);
    out.report = "vvinterpreter: " + t.line + replay_note + "\n" + t.stack;
    r.error = t.panel + replay_note + (t.stack.empty() ? "" : "\n" + t.stack);
  }
  return out;
}

}  // namespace vvi
