// The model controller: the one thing that drives the model. Keys, the
// panel, --script, batch mode and replays all give it commands
// (command.hpp); it runs them in order, the model's code as jobs
// (model_jobs.hpp), and keeps
//
// * the event log (event_log.hpp): every event that changed the model, so
//   that a reload, a restart, or the return to the last good state after
//   an error replays it and comes back to the same state;
// * the state record (state_record.hpp), told to the view before any job
//   starts, so a crash never repeats what it crashed in;
// * the facts the panel shows (model_facts.hpp), which stay valid while a
//   job runs.
//
// It uses no GL: whatever draws is a controller_view.
#pragma once

#include <deque>
#include <functional>
#include <future>
#include <optional>
#include <string>

#include "app/options.hpp"
#include "control/command.hpp"
#include "control/controller_view.hpp"
#include "control/event_log.hpp"
#include "control/model_facts.hpp"
#include "control/model_jobs.hpp"
#include "control/recording.hpp"
#include "control/state_record.hpp"
#include "control/wake_signal.hpp"
#include "runner/model_runner.hpp"

namespace vvi {

struct controller_policy {
  //! After an error in a step, end, action or pick, the model comes back
  //! to its last good state (replaying the log). Off (batch): the first
  //! error ends the run (failed()).
  bool restore_after_error = true;
  //! An edit is first run as a quick build (compile/quick_build.hpp) while
  //! the optimised build compiles; that is then loaded in its place and
  //! the log replayed on it. Off (batch): builds come from elsewhere.
  bool swap_in_optimised = true;
};

class model_controller {
 public:
  //! `from`: the record of a viewer that died (restarted), or a fresh one.
  model_controller(const options& o, model_jobs& jobs, controller_view& view, const state_record& from = {},
                   controller_policy policy = {});
  ~model_controller();
  model_controller(const model_controller&) = delete;
  model_controller& operator=(const model_controller&) = delete;

  //! A command from anyone. `stop` acts at once; a command of the view that
  //! does not read the model (rotate, zoom, show, ...) too, when nothing is
  //! queued; everything else is queued and carried out by poll().
  void submit(const command& c);
  //! Ends finished builds and jobs, starts what is next; `now` in seconds
  //! (animation, wait). With inline jobs, runs until nothing can go on.
  void poll(double now);
  //! Loads a build made elsewhere (batch) and replays `log` on it.
  void load_build(const build_result& b, const event_log& log);
  //! Runs the model's close block and unloads it (the window closes, the
  //! batch run ends); "" or the error.
  std::string close_model();

  //! Nothing queued, running, building or loading, the view caught up: a
  //! script's next command may go.
  bool idle() const;
  //! Only a job runs (a script's `wait` and `window-screenshot` go beside it).
  bool only_a_job_runs() const;
  bool busy() const { return jobs_.busy(); }
  //! How long the window may wait for events before there is something to
  //! do (0: now): the end of a `wait`, the next frame of an animation; a
  //! job or a build that ends wakes it (build_ended(), the jobs' own).
  double seconds_until_due(double now) const;
  //! Called from a build's thread when the build ends.
  wake_signal& build_ended() { return build_ended_; }
  //! The view has shown what it was asked to (pictures taken, states drawn).
  bool view_caught_up() const { return view_.caught_up(); }
  bool building() const { return building_; }
  //! The optimised build of the quick build that runs is compiling.
  bool optimising() const { return optimising_; }
  bool animating() const { return animating_; }
  double job_seconds() const { return jobs_.busy_seconds(); }
  std::string job_what() const { return jobs_.what(); }
  //! "running", "compiling ...", ...
  const std::string& status() const { return status_; }
  const std::string& warnings() const { return warnings_; }
  //! The model's state, as the last job left it.
  const model_facts& facts() const { return facts_; }
  const model_runner& runner() const { return runner_; }
  const state_record& record() const { return record_; }
  const event_log& log() const { return log_; }
  //! Whether an error ended the run (policy without restore_after_error).
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }

  //! The series being recorded ("FILE every K steps"), for the panel.
  std::vector<std::string> recorded_files() const;
  bool recording() const { return !recording_.empty(); }
  //! Ends the recording where it is (the window closes): its movies are
  //! put in place with the frames they have; "" or the error.
  std::string finish_recording() { return stop_recording(false, true); }

  // The parts of the record others keep.
  void update_view(const view_record& v);
  void set_script_position(std::size_t n);
  void set_up();
  void set_quitting();

 private:
  // A fresh instance of a plugin, then the events of `log` replayed on it.
  struct load_plan {
    std::string plugin;
    event_log log;
    std::string message;  // said when it is done
    bool trying = false;  // a new build: the last good model stays in the record until it is done
    bool keep_error = false;
    bool restore_on_error = true;  // a failed event of the replay: replay again up to it
    bool goes_on = false;          // the optimised build swapped in: animation and steps asked for go on
  };
  struct replay_state {
    load_plan plan;
    std::size_t next = 0;
    event_log done;
    unsigned long steps_in_event = 0;
    std::string error;
  };

  bool start_next(double now);
  //! false when the command must wait (a view that is not ready).
  bool carry_out(const command& c, double now);
  void run_job(const std::string& activity, const std::string& what, std::function<bool()> work,
               std::function<void(bool)> then);
  void refresh_facts();
  void flush_record();
  void stop();
  // Model commands (model_controller.cpp).
  void run_step(bool user);
  void run_event(const command& c);
  bool runs_nothing(const command& c) const;
  void event_done(const command& c, bool ok, const std::string& error);
  void set_parameter(const command& c);
  void write_out(const command& c);
  void error(const std::string& shown, const std::string& line);
  //! The view is told, then the series recorded (control/recording.cpp).
  void changed(const model_change& c);
  // Time series (control/recording.cpp).
  void record(const command& c);
  std::string write_series(recorded_series& s);
  std::string stop_recording(bool write_last, bool keep_movies);
  void recording_failed(const std::string& e);
  // Builds, loads and replays (model_loads.cpp).
  void start_build(bool force);
  void finish_build();
  void start_optimising();
  void finish_optimising();
  void swap_in_optimised();
  std::optional<load_plan> plan_for(const build_result& b);
  void begin_load();
  void loaded(bool ok);
  void replay_next();
  void replayed(bool ok);
  void finish_load();
  void restore_after_error();
  bool carry_event(const command& c, unsigned long& steps, std::string& error);
  std::string model_name() const { return o_.model; }

  options o_;
  model_jobs& jobs_;
  controller_view& view_;
  controller_policy policy_;
  model_runner runner_;
  state_record record_;
  std::string sent_;  // the record line the view has
  event_log log_;
  model_facts facts_;
  std::deque<command> queue_;
  std::vector<recorded_series> recording_;
  unsigned long steps_left_ = 0;  // of the step or run command going on
  bool animating_ = false;
  double now_ = 0, last_animated_ = 0, wait_until_ = 0;
  std::function<void(bool)> then_;  // the running job's follow-up
  bool job_ok_ = false;
  std::string activity_;            // what the running job is, for Stop ("step", "loading", ...)
  std::optional<load_plan> load_;   // to start
  std::optional<load_plan> loading_;
  std::optional<replay_state> replay_;
  bool resume_pending_ = false;     // the first build after a restart
  bool keep_error_once_ = false;
  bool building_ = false, build_cached_ = false;
  wake_signal build_ended_;  // before the builds' futures, whose threads call it
  // Set, they stop the build's or the optimised build's compiler: when the
  // controller closes, and for a stale optimised build once a newer
  // program compiles (before the futures, whose threads read them).
  std::atomic<bool> cancel_build_{false}, cancel_optimised_{false};
  unsigned long builds_taken_ = 0;  // results taken from those futures
  std::future<build_result> build_;
  // The optimised build beside a quick one, and the build it is for (a
  // newer build makes it stale: it is then made again for that one).
  bool optimising_ = false, optimise_again_ = false;
  unsigned long builds_started_ = 0, optimising_for_ = 0;
  std::future<build_result> optimised_;
  std::optional<build_result> optimised_build_;  // done, to load once no other load is under way
  std::string status_ = "starting", warnings_, failure_;
};

}  // namespace vvi
