#include "control/model_controller.hpp"

#include <algorithm>
#include <cstdio>

#include <vv/io/files.hpp>

#include "app/joined_names.hpp"
#include "control/command_text.hpp"
#include "runner/output_file.hpp"
#include "runner/parameter_source.hpp"
#include "runner/plots.hpp"

namespace vvi {

namespace {

// Commands that need neither the model nor the queue's order when nothing
// is queued: they are carried out at once, also while a job runs.
bool goes_beside_jobs(command::kind_t k) {
  switch (k) {
    case command::rotate:
    case command::zoom:
    case command::reset_view:
    case command::show:
    case command::color_by:
    case command::window_screenshot:
    case command::replay:
    case command::rewind_on_change:
    case command::wait:
    case command::reload:     // a build runs beside the model
    case command::recompile:
    case command::quit: return true;
    default: return false;
  }
}

std::vector<std::string> comma_list(const std::string& names) {
  std::vector<std::string> out;
  for (std::size_t from = 0, comma; from <= names.size(); from = comma + 1) {
    comma = names.find(',', from);
    if (comma == std::string::npos) comma = names.size();
    out.push_back(names.substr(from, comma - from));
  }
  return out;
}

}  // namespace

model_controller::model_controller(const options& o, model_jobs& jobs, controller_view& view,
                                   const state_record& from, controller_policy policy)
    : o_(o), jobs_(jobs), view_(view), policy_(policy), runner_(o), record_(from) {
  if (from.restarted) {
    resume_pending_ = true;
    keep_error_once_ = true;  // the reason for the restart stays shown
    log_ = from.log;
  } else {
    log_.initial = runner_.parameter_settings();  // --set: the values the first load starts with
  }
  // What this process tells its supervisor starts afresh.
  record_.restarted = false;
  record_.up = record_.quitting = false;
  record_.error.clear(), record_.note.clear(), record_.stopped.clear(), record_.stopped_activity.clear();
}

model_controller::~model_controller() {
  // Closing: no compiler is waited for, nor left running.
  cancel_build_ = true;
  cancel_optimised_ = true;
  if (building_) build_.wait();
  if (optimising_) optimised_.wait();
}

void model_controller::submit(const command& c) {
  if (c.kind == command::stop) return stop();
  if (queue_.empty() && goes_beside_jobs(c.kind) && carry_out(c, now_)) return flush_record();
  queue_.push_back(c);
}

void model_controller::poll(double now) {
  now_ = now;
  finish_build();
  finish_optimising();
  swap_in_optimised();
  for (;;) {
    if (jobs_.take_finished() && then_) {
      std::function<void(bool)> then = std::move(then_);
      then_ = nullptr;
      then(job_ok_);
      std::fflush(stdout);  // what the model printed shows now, also through a pipe
    }
    if (jobs_.busy() || !view_.caught_up() || failed() || !start_next(now)) break;
  }
  flush_record();
}

bool model_controller::idle() const {
  return queue_.empty() && !jobs_.busy() && !building_ && !optimising_ && !optimised_build_ && !load_ && !loading_ &&
         !replay_ && steps_left_ == 0 && now_ >= wait_until_ && view_.caught_up();
}

double model_controller::seconds_until_due(double now) const {
  constexpr double longest = 0.25;  // an idle window's pace: the file watch
  if (build_ended_.times() > builds_taken_) return 0;  // its result is a moment away
  if (!view_.caught_up()) return 0;
  if (jobs_.busy()) return 0.1;  // its end wakes the loop; the panel counts its seconds
  if (load_ || loading_ || replay_ || steps_left_ > 0) return 0;
  if (optimised_build_) return 0.02;
  double due = longest;
  if (now < wait_until_) due = std::min(due, wait_until_ - now);
  else if (!queue_.empty()) return 0.02;  // held up by what the view has still to do
  if (animating_ && runner_.model())
    due = std::min(due, std::max(0.0, last_animated_ + facts_.delay_msec / 1000.0 - now));
  return due;  // a build's end wakes the loop
}

bool model_controller::only_a_job_runs() const {
  return jobs_.busy() && queue_.empty() && !building_ && !load_ && !loading_ && !replay_ && steps_left_ == 0 &&
         now_ >= wait_until_;
}

// What runs next when the model is free: a load (a build, a rewind, a
// restore) and its replay first, then the steps of the command going on,
// then the queue, then the animation.
bool model_controller::start_next(double now) {
  if (load_) return begin_load(), true;
  if (replay_) return replay_next(), true;
  if (loading_) return false;
  if (steps_left_ > 0) {
    --steps_left_;
    run_step(true);
    return true;
  }
  if (now < wait_until_) return false;
  if (!queue_.empty()) {
    // Taken off first: carrying it out may clear the queue (an error in batch).
    command next = queue_.front();
    queue_.pop_front();
    if (carry_out(next, now)) return true;
    queue_.push_front(next);  // the view is not ready for it yet
    return false;
  }
  if (animating_ && runner_.model() && now - last_animated_ >= facts_.delay_msec / 1000.0) {
    last_animated_ = now;
    run_step(true);
    return true;
  }
  return false;
}

bool model_controller::carry_out(const command& c, double now) {
  bool model = runner_.model() != nullptr;
  switch (c.kind) {
    case command::step: steps_left_ = model ? c.number : 0; return true;
    case command::run: steps_left_ = model ? facts_.run_steps : 0; return true;
    case command::animate: animating_ = model && facts_.can_animate; return true;
    case command::stop: stop(); return true;
    case command::rewind:
      if (!runner_.plugin_path().empty())
        load_ = load_plan{runner_.plugin_path(), event_log{runner_.parameter_settings(), {}}, "rewound " + o_.model};
      return true;
    case command::resume:
      if (runner_.plugin_path().empty()) {
        std::string e = "resume " + c.path + ": no model is loaded";
        error(e, e);
      } else {
        load_ = load_plan{runner_.plugin_path(), event_log{{}, {}, c.path}, "resumed " + o_.model + " from " + c.path};
      }
      return true;
    case command::end:
    case command::reread:
    case command::action:
    case command::pick_action:
      if (model) run_event(c);
      return true;
    case command::set: set_parameter(c); return true;
    case command::reload: start_build(false); return true;
    case command::recompile: start_build(true); return true;
    case command::export_mesh:
    case command::plots:
    case command::save_params:
    case command::save_session:
    case command::checkpoint: write_out(c); return true;
    case command::record: record(c); return true;
    case command::replay: record_.replay = c.on; return true;
    case command::rewind_on_change: record_.rewind_on_change = c.on; return true;
    case command::wait: wait_until_ = now + c.number / 1000.0; return true;
    default: return view_.view(c);
  }
}

// The record first: a job that crashes the process must not be run again
// by the window that comes back.
void model_controller::run_job(const std::string& activity, const std::string& what, std::function<bool()> work,
                               std::function<void(bool)> then) {
  activity_ = activity;
  runner_.clear_error();
  flush_record();
  then_ = std::move(then);
  jobs_.submit([this, work] { job_ok_ = work(); }, what);
}

void model_controller::refresh_facts() { facts_ = read_facts(runner_.model(), runner_.file_objects()); }

void model_controller::flush_record() {
  std::string line = record_line(record_);
  if (line == sent_) return;
  sent_ = line;
  view_.record_changed(record_);
}

// Stop: the animation, the steps to come, and a running job (which only
// a new process can end).
void model_controller::stop() {
  animating_ = false;
  steps_left_ = 0;
  if (!jobs_.busy()) return;
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.1f", jobs_.busy_seconds());
  record_.stopped_activity = activity_;
  record_.stopped = jobs_.what() + " was stopped after " + secs + " s";
  flush_record();
  view_.abandon_job();
}

void model_controller::error(const std::string& shown, const std::string& line) {
  view_.show_error(shown, line);
  if (!policy_.restore_after_error) {
    failure_ = line;
    queue_.clear();
    steps_left_ = 0;
  }
}

void model_controller::run_step(bool) {
  run_job("step", "step " + std::to_string(facts_.steps + 1), [this] { return runner_.step(); },
          [this](bool ok) {
            if (!ok) {
              steps_left_ = 0;
              animating_ = false;
              error(runner_.error(), runner_.error());
              return restore_after_error();
            }
            log_.append(command::steps(1));
            record_.log = log_;
            refresh_facts();
            changed({model_change::stepped});
          });
}

// An action the program does not have, or a pick without a pick block:
// none of the model's code runs, so there is nothing to restore.
bool model_controller::runs_nothing(const command& c) const {
  if (c.kind == command::pick_action) return !facts_.has_pick;
  if (c.kind != command::action) return false;
  return std::none_of(facts_.actions.begin(), facts_.actions.end(),
                      [&c](const action_view& a) { return a.name == c.name; });
}

void model_controller::run_event(const command& c) {
  if (runs_nothing(c)) {
    // The runner says why, without running the model.
    std::string why;
    unsigned long steps = 0;
    carry_event(c, steps, why);
    return error(why, why);
  }
  std::string activity = c.kind == command::pick_action ? "pick" : command_word(c.kind);
  std::string what = c.kind == command::end || c.kind == command::reread ? activity : command_text(c);
  auto failure = std::make_shared<std::string>();
  run_job(
      activity, what,
      [this, c, failure] {
        unsigned long steps = 0;
        return carry_event(c, steps, *failure);
      },
      [this, c, failure](bool ok) { event_done(c, ok, *failure); });
}

void model_controller::event_done(const command& c, bool ok, const std::string& failure) {
  if (!ok) {
    error(failure, failure);
    // A file that does not read leaves the model as it was; anything else
    // may have left it half changed.
    if (c.kind != command::reread) restore_after_error();
    return;
  }
  log_.append(c);
  record_.log = log_;
  refresh_facts();
  if (c.kind == command::reread && !facts_.file_objects.empty()) view_.say("reread " + joined_names(facts_.file_objects));
  changed({model_change::changed});
}

// A parameter is host memory of the model: set between jobs, on this thread.
void model_controller::set_parameter(const command& c) {
  std::string e = runner_.set_parameter(c.name, c.value);
  if (!e.empty()) return error(e, e);
  view_.say("set " + c.name + " = " + c.value);
  if (record_.rewind_on_change) {
    // The run as if the parameter had had this value from the start.
    event_log again = log_;
    set_setting(again.initial, c.name, c.value);
    std::vector<command> kept;
    for (const command& event : again.events)
      if (event.kind != command::set || event.name != c.name) kept.push_back(event);
    again.events = kept;
    load_ = load_plan{runner_.plugin_path(), again, "rewound " + o_.model};
    return;
  }
  log_.append(c);
  record_.log = log_;
  refresh_facts();
  changed({model_change::changed});
}

void model_controller::write_out(const command& c) {
  std::string e;
  if (!runner_.model() && c.kind != command::save_session) {
    e = std::string(command_word(c.kind)) + (c.path.empty() ? "" : " " + c.path) + ": no model is loaded";
    return error(e, e);
  }
  if (c.kind == command::export_mesh) {
    e = c.name.empty() ? runner_.export_to(c.path) : runner_.export_to(c.path, comma_list(c.name));
  } else if (c.kind == command::plots) {
    e = write_plots(c.path, runner_.model()->plots());
  } else if (c.kind == command::checkpoint) {
    e = runner_.save_checkpoint(c.path);
  } else if (c.kind == command::save_session) {
    std::string text = "# vv session of " + o_.model + ": vvinterpreter --batch --replay FILE MODEL runs it\n" +
                       log_.text();
    e = write_output(c.path, [&](const std::string& to) -> std::string {
      try {
        vv::io::write_text_file(to, text);
      } catch (const std::exception& x) {
        return x.what();
      }
      return "";
    });
  } else {  // save-params: only what the user set; the others stay as the file writes them
    std::vector<parameter_value_at> values;
    for (const parameter_setting& set : runner_.parameter_settings())
      if (const vv_param_entry* p = find_parameter(*runner_.model(), set.name))
        values.push_back({p->name, parameter_text(*p), p->line});
    if (values.empty()) return view_.say("no parameter was changed: nothing to save");
    e = save_parameter_values(o_.model, values);
    if (e.empty()) return view_.say("saved the parameters in " + o_.model);
  }
  if (e.empty()) view_.wrote(c.path);
  else error(e, e);
}

std::string model_controller::close_model() {
  runner_.clear_error();
  runner_.close();
  return runner_.error();
}

void model_controller::update_view(const view_record& v) { record_.view = v; }
void model_controller::set_script_position(std::size_t n) { record_.script_pos = n; }
void model_controller::set_up() {
  record_.up = true;
  flush_record();
}
void model_controller::set_quitting() {
  record_.quitting = true;
  flush_record();
}

}  // namespace vvi
