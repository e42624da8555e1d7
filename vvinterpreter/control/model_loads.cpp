// The model controller's builds, loads and replays: a fresh instance of a
// plugin, started with the parameter values the log began with, then the
// log's events one job each. While a new build is tried, the record keeps
// the last good model and its log (a crash brings that back); while the
// same plugin replays, the record names the event being replayed (a crash
// stops the replay there).
#include "control/command_text.hpp"
#include "control/model_controller.hpp"

namespace vvi {

void model_controller::start_build(bool force) {
  if (building_) return;
  building_ = true;
  ++builds_started_;
  optimised_build_.reset();  // of the program before this build
  status_ = force ? "recompiling ..." : "compiling ...";
  view_.build_started();
  controller_view* view = &view_;
  const model_runner* runner = &runner_;
  // Recompile asks for the optimised build itself.
  model_runner::build_kind kind = policy_.swap_in_optimised && !force ? model_runner::build_kind::quick_first
                                                                      : model_runner::build_kind::usual;
  wake_signal* ended = &build_ended_;
  std::atomic<bool>* cancel = &cancel_build_;
  std::atomic<bool>* stale_optimised = &cancel_optimised_;
  cancel->store(false);
  build_ = std::async(std::launch::async, [runner, force, view, kind, ended, cancel, stale_optimised] {
    auto compiling = [view, stale_optimised] {
      // A new program: the optimised build of the one before would only be
      // thrown away, and holds up this one's.
      stale_optimised->store(true);
      view->compiling();
    };
    build_result b = runner->build(force, compiling, kind, cancel);
    (*ended)();
    return b;
  });
}

// The optimised build of the quick build just made, beside its load.
void model_controller::start_optimising() {
  if (optimising_) {
    optimise_again_ = true;  // once the stale one is done
    return;
  }
  optimising_ = true;
  optimise_again_ = false;
  optimising_for_ = builds_started_;
  const model_runner* runner = &runner_;
  wake_signal* ended = &build_ended_;
  std::atomic<bool>* cancel = &cancel_optimised_;
  cancel->store(false);
  optimised_ = std::async(std::launch::async, [runner, ended, cancel] {
    build_result b = runner->build(false, {}, model_runner::build_kind::behind_quick, cancel);
    (*ended)();
    return b;
  });
}

void model_controller::finish_optimising() {
  if (!optimising_ || optimised_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  optimising_ = false;
  build_result b = optimised_.get();
  ++builds_taken_;
  if (b.cancelled || optimise_again_ || optimising_for_ != builds_started_ || building_) {
    // A newer build came meanwhile: its own optimised build follows it.
    if (optimise_again_ && !building_) start_optimising();
    return;
  }
  if (!b.ok) {
    // g++ refused what clang took: its messages; the quick build keeps running.
    error(b.details.empty() ? b.error : b.details, b.error);
    status_ = "running an unoptimised build: the optimised one failed";
    return;
  }
  warnings_ = b.warnings;
  optimised_build_ = std::move(b);
}

// Once the quick build has loaded and replayed (its "reloaded" said), and
// no other load waits, the optimised build takes its place.
void model_controller::swap_in_optimised() {
  if (!optimised_build_ || load_ || loading_ || replay_ || building_) return;
  build_result b = std::move(*optimised_build_);
  optimised_build_.reset();
  if (b.plugin == record_.plugin || !runner_.model()) return;
  // The same program, so the same state: its log replayed whatever the
  // replay setting (a reload of an edit may start afresh; this may not).
  load_ = load_plan{b.plugin, log_, "swapped in the optimised build of " + o_.model, true, true, true, true};
}

void model_controller::finish_build() {
  if (!building_ || build_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  building_ = false;
  build_result b = build_.get();
  ++builds_taken_;
  view_.build_finished(b);
  if (!b.ok) {
    // The last good model keeps running.
    error(b.details.empty() ? b.error : b.details, b.error);
    status_ = runner_.model() || load_ ? "running the last model that compiled" : "no model";
    return;
  }
  warnings_ = b.warnings;
  build_cached_ = b.cached;
  load_ = plan_for(b);
  if (b.quick && load_) start_optimising();
}

// What a finished build loads, and with which events.
std::optional<model_controller::load_plan> model_controller::plan_for(const build_result& b) {
  std::string cached = b.cached ? " (cached)" : "";
  if (resume_pending_) {
    // After a restart: a build that crashed on its way in is not loaded
    // again as it is; the model that ran before comes back.
    resume_pending_ = false;
    if (b.plugin == record_.bad_plugin) {
      if (record_.plugin.empty() || record_.plugin == record_.bad_plugin) {
        status_ = "no model: it crashed while loading; edit it to try again";
        return std::nullopt;
      }
      return load_plan{record_.plugin, record_.log, "loaded " + o_.model + cached, false, true};
    }
    return load_plan{b.plugin, record_.log, "loaded " + o_.model + cached, b.plugin != record_.plugin, true};
  }
  bool first = !runner_.model();
  event_log log = record_.replay ? log_ : event_log{runner_.parameter_settings(), {}};
  // --resume: the first model goes on from the checkpoint.
  if (first && log.events.empty() && log.resumed_from.empty()) log.resumed_from = o_.resume;
  std::string quick = b.quick ? " (unoptimised until its optimised build is ready)" : "";
  return load_plan{b.plugin, log, (first ? "loaded " : "reloaded ") + o_.model + cached + quick,
                   b.plugin != record_.plugin && !record_.plugin.empty()};
}

void model_controller::load_build(const build_result& b, const event_log& log) {
  build_cached_ = b.cached;
  load_ = load_plan{b.plugin, log, "loaded " + o_.model, false};
}

void model_controller::begin_load() {
  loading_ = std::move(*load_);
  load_.reset();
  const load_plan& plan = *loading_;
  if (plan.trying) {
    record_.trying = plan.plugin;
  } else {
    record_.plugin = plan.plugin;
    record_.log = plan.log;
  }
  record_.replaying = -1;
  status_ = "loading ...";
  std::vector<parameter_setting> before = runner_.parameter_settings();
  std::string plugin = plan.plugin;
  std::vector<parameter_setting> initial = plan.log.initial;
  std::string resume = plan.log.resumed_from;
  unsigned long steps = plan.log.steps();
  std::string what = resume.empty() ? "loading" : "loading from " + resume;
  if (steps) what += resume.empty() ? " and running to step " + std::to_string(steps)
                                    : " and running " + std::to_string(steps) + " steps";
  run_job("loading", what,
          [this, plugin, initial, resume] {
            runner_.use_settings(initial);
            return runner_.load(plugin, 0, resume);
          },
          [this, before](bool ok) {
            if (!ok) runner_.use_settings(before);
            loaded(ok);
          });
}

void model_controller::loaded(bool ok) {
  load_plan& plan = *loading_;
  if (!ok) {
    // The running model (if any) stays as it was.
    record_.trying.clear();
    if (!plan.trying) record_.log = log_;
    error(runner_.error(), runner_.error());
    status_ = runner_.model() ? "running" : "no model";
    loading_.reset();
    return;
  }
  replay_state r;
  r.plan = std::move(plan);
  r.done.initial = runner_.parameter_settings();  // as the model took them
  r.done.resumed_from = r.plan.log.resumed_from;
  loading_.reset();
  replay_ = std::move(r);
  refresh_facts();
  if (replay_->plan.log.events.empty()) finish_load();
}

void model_controller::replay_next() {
  replay_state& r = *replay_;
  const command event = r.plan.log.events[r.next];
  if (!r.plan.trying) record_.replaying = static_cast<long>(r.next);
  unsigned long done_before = r.done.steps();
  std::string what = event.kind == command::step ? "step " + std::to_string(done_before + 1) +
                                                       (event.number > 1 ? " to " + std::to_string(done_before + event.number) : "")
                                                 : command_text(event);
  std::string activity = event.kind == command::pick_action ? "pick" : command_word(event.kind);
  run_job(activity, "replaying " + what,
          [this, event] {
            replay_->error.clear();
            replay_->steps_in_event = 0;
            return carry_event(event, replay_->steps_in_event, replay_->error);
          },
          [this](bool ok) { replayed(ok); });
}

void model_controller::replayed(bool ok) {
  replay_state& r = *replay_;
  const command& event = r.plan.log.events[r.next];
  if (ok) {
    r.done.append(event);
  } else {
    // The replay stops at this event: the model is as the events before
    // it (and the steps of it that ran) left it.
    if (event.kind == command::step && r.steps_in_event > 0) r.done.append(command::steps(r.steps_in_event));
    std::string where = "the replay stopped at event " + std::to_string(r.next + 1) + " of " +
                        std::to_string(r.plan.log.events.size()) + " (" + command_text(event) + ")";
    error(r.error + "\n" + where, r.error + "; " + where);
    // The failed event may have left the model half changed: the events
    // that worked, replayed once more on a fresh instance, do not.
    bool half_done = event.kind != command::set && event.kind != command::reread;
    if (policy_.restore_after_error && r.plan.restore_on_error && half_done) {
      load_plan again{r.plan.plugin, r.done,
                      "restored " + o_.model + " to step " + std::to_string(r.done.steps()) +
                          ", where the replay stopped",
                      false, true, false};
      replay_.reset();
      load_ = std::move(again);
      return;
    }
    r.plan.keep_error = true;
    r.next = r.plan.log.events.size();
  }
  ++r.next;
  if (r.next >= r.plan.log.events.size()) finish_load();
  else refresh_facts();
}

void model_controller::finish_load() {
  replay_state r = std::move(*replay_);
  replay_.reset();
  log_ = r.done;
  record_.plugin = r.plan.plugin;
  record_.log = log_;
  record_.trying.clear();
  record_.replaying = -1;
  // A swap goes on as the quick build went; a new model waits for the user.
  if (!r.plan.goes_on) animating_ = false, steps_left_ = 0;
  status_ = optimising_ ? "running (unoptimised while the optimised build compiles)" : "running";
  if (!r.plan.keep_error && !keep_error_once_) view_.clear_error();
  keep_error_once_ = false;
  refresh_facts();
  view_.say(r.plan.message);
  changed({model_change::loaded});
}

// After an error in a step, end, action or pick the model may be half
// changed: it runs again through its log to its last good state (or from
// start, when replaying is off), so the model, its panel and its drawing
// agree.
void model_controller::restore_after_error() {
  if (!policy_.restore_after_error || runner_.plugin_path().empty()) return;
  std::string plugin = runner_.plugin_path();
  if (record_.replay)
    // The step the facts have counts a checkpoint's steps too (the log's do not).
    load_ = load_plan{plugin, log_, "restored " + o_.model + " to step " + std::to_string(facts_.steps) +
                                        ", its last good state", false, true};
  else
    load_ = load_plan{plugin, event_log{log_.settings_after(), {}},
                      "restarted " + o_.model + " at step 0 (running again to the last step is off)", false, true};
}

// One event on the model (on the job's thread): a step event's steps,
// counted as they are done.
bool model_controller::carry_event(const command& c, unsigned long& steps, std::string& failure) {
  bool ok = true;
  switch (c.kind) {
    case command::step:
      for (steps = 0; steps < c.number; ++steps)
        if (!runner_.step()) return failure = runner_.error(), false;
      return true;
    case command::end: ok = runner_.end(); break;
    case command::reread: ok = runner_.reread(); break;
    case command::set: failure = runner_.set_parameter(c.name, c.value); return failure.empty();
    case command::action: ok = runner_.run_action(c.name); break;
    case command::pick_action: ok = runner_.run_pick(static_cast<unsigned>(c.number)); break;
    default: return true;
  }
  if (!ok) failure = runner_.error();
  return ok;
}

}  // namespace vvi
