#include "batch/batch.hpp"

#include <fcntl.h>
#include <string.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "app/files.hpp"
#include "batch/batch_view.hpp"
#include "control/command_text.hpp"
#include "control/model_controller.hpp"
#include "runner/crash_report.hpp"
#include "runner/supervisor.hpp"
#include "series/step_names.hpp"

namespace vvi {

namespace {

int fail(const std::string& why) {
  std::fprintf(stderr, "vvinterpreter: %s\n", why.c_str());
  return 1;
}

void report_build(const options& o, const build_result& b) {
  if (!b.warnings.empty()) std::fprintf(stderr, "%s", b.warnings.c_str());
  if (o.quiet) return;
  if (b.cached) std::printf("%s: compiled model found in the cache\n", o.model.c_str());
  else std::printf("%s: translated in %.0f ms, compiled in %.2f s%s\n", o.model.c_str(), b.translate_ms,
                   b.compile_ms / 1000, b.quick ? " (a quick build: unoptimised)" : "");
}

// --list-params: the parameters as the file and --set give them, before
// start (which does not run).
int list_parameters(const options& o, const build_result& b) {
  if (!b.warnings.empty()) std::fprintf(stderr, "%s", b.warnings.c_str());
  std::string error;
  std::unique_ptr<session> model = session::load(b.plugin, session_settings_for(o), error);
  if (!model) return fail(error);
  model->skip_close();  // it never started
  std::vector<parameter_setting> settings;
  for (const auto& [name, text] : o.parameter_values) settings.push_back({name, "", text});
  std::string refused = apply_parameter_settings(*model, settings, o.model);
  if (!refused.empty()) return fail(refused);
  for (const vv_param_entry* p : parameters_of(*model)) std::printf("%s\n", parameter_line(*p).c_str());
  return 0;
}

// --replay FILE: the session's events, after the values of --set.
bool read_session(const options& o, event_log& log, std::string& error) {
  log.initial.clear();
  for (const auto& [name, text] : o.parameter_values) set_setting(log.initial, name, text);
  log.resumed_from = o.resume;
  if (o.replay.empty()) return true;
  std::optional<std::string> text = read_file(o.replay);
  if (!text) return error = o.replay + ": cannot read the session", false;
  event_log session;
  if (!event_log::parse(*text, o.replay, session, error)) return false;
  if (!session.resumed_from.empty() && !o.resume.empty())
    return error = o.replay + ": the session goes on from the checkpoint " + session.resumed_from +
                   ", and --resume names another start (" + o.resume + ")",
           false;
  for (const parameter_setting& s : session.initial) set_setting(log.initial, s.name, s.text);
  log.events = session.events;
  if (log.resumed_from.empty()) log.resumed_from = session.resumed_from;
  return true;
}

// The batch run's commands, one after another; "" or why the run ends.
class batch_run {
 public:
  batch_run(model_controller& c, batch_view& v) : c_(c), v_(v) {}
  std::string operator()(const command& cmd) {
    c_.submit(cmd);
    c_.poll(0);
    return c_.failed() ? c_.failure() : v_.failure();
  }

 private:
  model_controller& c_;
  batch_view& v_;
};

// The steps, with --action and --pick-action after the steps they name.
std::string run_steps(const options& o, model_controller& c, batch_run& run, double& seconds) {
  unsigned long first = c.facts().steps, last = first + o.steps;
  std::vector<std::pair<unsigned long, command>> events = o.events_at;
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [step, event] : events)
    if (step < first || step > last)
      return "--" + std::string(event.kind == command::action ? "action " + event.name : "pick-action " +
                                std::to_string(event.number)) + "@" + std::to_string(step) +
             ": the run goes from step " + std::to_string(first) + " to step " + std::to_string(last);
  seconds = 0;
  auto steps_to = [&](unsigned long target) -> std::string {
    unsigned long now = c.facts().steps;
    if (target <= now) return "";
    auto t0 = std::chrono::steady_clock::now();
    std::string e = run(command::steps(target - now));
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return e;
  };
  for (const auto& [step, event] : events) {
    if (std::string e = steps_to(step); !e.empty()) return e;
    if (std::string e = run(event); !e.empty()) return e;
  }
  return steps_to(last);
}

// --every: a `record` command for each file option, {step} as wide as
// the last step; only the pictures when `pictures_only`.
std::vector<command> series_commands(const options& o, unsigned long last_step, bool pictures_only) {
  std::vector<command> out;
  for (const std::string* file : {&o.export_path, &o.screenshot}) {
    if (file->empty() || (pictures_only && file == &o.export_path)) continue;
    out.push_back(command::recording(o.every, *file, digits_of(last_step)));
  }
  return out;
}

// One run of the model from its start (or its checkpoint): the session's
// events, the steps (with the series of --every), --checkpoint, the end
// block; "" or the error. A run that only measures (`pictures_only`) saves
// no checkpoint.
std::string run_model(const options& o, model_controller& c, batch_view& view, const build_result& b,
                      const event_log& log, bool pictures_only, double& seconds) {
  c.load_build(b, log);
  c.poll(0);
  if (c.failed()) return c.failure();
  view.count_steps_from(c.facts().steps);
  batch_run run(c, view);
  if (o.every)
    for (const command& record : series_commands(o, c.facts().steps + o.steps, pictures_only))
      if (std::string e = run(record); !e.empty()) return e;
  if (std::string e = run_steps(o, c, run, seconds); !e.empty()) return e;
  if (!o.checkpoint.empty() && !pictures_only)
    if (std::string e = run(command::with_path(command::checkpoint, o.checkpoint)); !e.empty()) return e;
  if (o.end_block)
    if (std::string e = run(command::of(command::end)); !e.empty()) return e;
  if (o.every)
    if (std::string e = run(command::record_off()); !e.empty()) return e;
  return "";
}

// Standard output goes nowhere while it lives (the model's printing in a
// run that only measures).
class silenced_stdout {
 public:
  silenced_stdout() {
    std::fflush(stdout);
    saved_ = ::dup(STDOUT_FILENO);
    int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) ::dup2(null, STDOUT_FILENO), ::close(null);
  }
  ~silenced_stdout() {
    std::fflush(stdout);
    if (saved_ >= 0) ::dup2(saved_, STDOUT_FILENO), ::close(saved_);
  }
  silenced_stdout(const silenced_stdout&) = delete;
  silenced_stdout& operator=(const silenced_stdout&) = delete;

 private:
  int saved_ = -1;
};

// A series of screenshots keeps one framing: the box that holds the model
// of every frame. It is known only at the end, so a first run, which
// writes nothing, finds it (models are deterministic: the second run goes
// through the same states). --frame gives it instead.
std::string measure_frame(const options& o, model_controller& c, batch_view& view, const build_result& b,
                          const event_log& log) {
  if (!o.quiet) std::printf("a first run finds the box that holds every frame (--frame gives it instead)\n");
  std::string e;
  {
    silenced_stdout quiet;
    view.measure_frame();
    double seconds = 0;
    e = run_model(o, c, view, b, log, true, seconds);
    if (e.empty()) e = c.close_model();
  }
  if (e.empty()) view.use_frame(view.measured());
  return e;
}

// The batch run itself, in the supervised child process.
int run_model_headless(const options& o) {
  inline_jobs jobs;
  batch_view view(o);
  model_controller c(o, jobs, view, {}, controller_policy{false, false});
  view.attach(c);
  // --expect-edits: the modelling loop, so an edit runs as a quick build.
  build_result b = c.runner().build(false, {}, o.expect_edits ? model_runner::build_kind::quick_first
                                                               : model_runner::build_kind::usual);
  if (!b.ok) return fail(b.error);
  if (o.list_params) return list_parameters(o, b);
  report_build(o, b);
  event_log log;
  std::string error;
  if (!read_session(o, log, error)) return fail(error);
  if (o.every && !o.screenshot.empty() && o.frame.empty())
    if (std::string e = measure_frame(o, c, view, b, log); !e.empty()) return fail(e);
  double seconds = 0;
  if (std::string e = run_model(o, c, view, b, log, false, seconds); !e.empty()) return fail(e);
  if (!o.quiet) {
    std::printf("%u steps in %.3f s\n", o.steps, seconds);
    for (const auto& [name, vertices] : c.facts().meshes) std::printf("mesh %s: %zu vertices\n", name.c_str(), vertices);
  }
  // Without --every, {step} in a name is the last step's number.
  unsigned long last = c.facts().steps;
  std::vector<command> outputs;
  if (!o.export_path.empty() && !o.every)
    outputs.push_back(command::with_path(command::export_mesh, name_at_step(o.export_path, last, 0)));
  for (unsigned label : o.picks) outputs.push_back(command::labelled(command::inspect, label));
  if (!o.plots_path.empty()) outputs.push_back(command::with_path(command::plots, o.plots_path));
  if (!o.screenshot.empty() && !o.every)
    outputs.push_back(command::with_path(command::screenshot, name_at_step(o.screenshot, last, 0)));
  batch_run run(c, view);
  for (const command& out : outputs)
    if (std::string e = run(out); !e.empty()) return fail(e);
  if (std::string e = c.close_model(); !e.empty()) return fail(e);
  return 0;
}

// While a block runs long, where it is (the supervisor asks the model).
void tell_long_activity(const options& o, const long_activity& a) {
  std::fprintf(stderr, "vvinterpreter: %s\n", describe_long_activity(a, o.model, o.step_timeout).c_str());
  std::fflush(stderr);
}

int report_end(const crash_text& t, const std::string& replay_note) {
  std::fprintf(stderr, "vvinterpreter: %s%s\n%s", t.line.c_str(), replay_note.c_str(), t.stack.c_str());
  return 1;
}

// A run that died while it replayed a session: the event it stopped at.
std::string replay_note(const options& o, const state_record& r) {
  if (r.replaying < 0 || static_cast<std::size_t>(r.replaying) >= r.log.events.size()) return "";
  return " (replaying event " + std::to_string(r.replaying + 1) + " of " + std::to_string(r.log.events.size()) +
         " of " + o.replay + ": " + command_text(r.log.events[static_cast<std::size_t>(r.replaying)]) + ")";
}

}  // namespace

int run_compile_only(const options& o) {
  build_result b = model_runner(o).build(false);
  if (!b.ok) {
    // The whole diagnosis is this mode's output; the reason is one line.
    if (!o.quiet) std::printf("%s", b.details.c_str());
    return fail(b.error);
  }
  report_build(o, b);
  if (!o.quiet) std::printf("%s\n", b.plugin.c_str());
  return 0;
}

int run_batch(const options& o) {
  // The model runs in a child process: a crash or a step past its time
  // limit ends the run with a message, not with this process.
  // --debug, --in-process: a debugger or profiler is the supervisor, and
  // it must see the model in this process.
  if (o.debug || o.in_process) return run_model_headless(o);
  supervision s;
  s.activity_timeout = o.step_timeout;
  s.notice_after = seconds_from_environment("VV_NOTICE_AFTER", 10);
  s.on_long_activity = [&](const long_activity& a) { tell_long_activity(o, a); };
  state_record heard;
  s.on_line = [&](const std::string& line) { read_record_line(line, heard); };
  child_end end = run_supervised([&] { return run_model_headless(o); }, s);
  int status = end.exit_code;
  if (end.kind == child_end::interrupted) {
    const char* name = sigabbrev_np(end.signal);
    fail(std::string("interrupted (SIG") + (name ? name : "?") + "); the files being written were removed");
    status = 128 + end.signal;
  } else if (end.kind == child_end::exited) {
    // Inside a block the model ended the process itself: its steps and
    // files are missing, whatever the status said.
    if (!end.activity.what.empty()) status = report_end(describe_exit(end, o.model), replay_note(o, heard));
  } else {
    status = report_end(describe_crash(end, o.model), replay_note(o, heard));
  }
  remove_module_copies(end);
  return status;
}

}  // namespace vvi
