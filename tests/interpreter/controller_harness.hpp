// The model controller in-process, for its tests: real models compiled
// once per test executable (state_models/), its jobs run at once on the
// test's thread, and a view that records what it was told.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "control/command_text.hpp"
#include "control/model_controller.hpp"
#include "control/script_player.hpp"
#include "in_process_options.hpp"
#include "test_files.hpp"

namespace controller_harness {

using vvi::command;

inline const std::string state_models = VV_TESTS_DIR "/state_models/";

inline vvi::options options_for(const std::string& model) {
  vvi::options o = in_process_options(state_models + model);
  o.quiet = true;
  return o;
}

// Each model is built once per test executable (then found in the cache).
inline const vvi::build_result& built(const std::string& model) {
  static std::map<std::string, vvi::build_result> builds;
  auto found = builds.find(model);
  if (found != builds.end()) return found->second;
  vvi::build_result b = vvi::model_runner(options_for(model)).build(false);
  EXPECT_TRUE(b.ok) << b.details;
  return builds[model] = b;
}

// What the controller told its view.
struct recording_view : vvi::controller_view {
  std::vector<std::string> said, errors;
  std::vector<vvi::state_record> records;
  std::vector<command> viewed;
  std::vector<vvi::model_change::kind_t> changes;
  void say(const std::string& m) override { said.push_back(m); }
  void show_error(const std::string&, const std::string& line) override { errors.push_back(line); }
  void record_changed(const vvi::state_record& r) override { records.push_back(r); }
  bool view(const command& c) override {
    viewed.push_back(c);
    return true;
  }
  void model_changed(const vvi::model_change& c) override { changes.push_back(c.kind); }
};

// Jobs run at once; each keeps the record the view had when it started.
struct recording_jobs : vvi::inline_jobs {
  explicit recording_jobs(const recording_view& v) : view(v) {}
  void submit(std::function<void()> job, const std::string& what) override {
    started.push_back(what);
    told.push_back(view.records.empty() ? vvi::state_record() : view.records.back());
    inline_jobs::submit(std::move(job), what);
  }
  const recording_view& view;
  std::vector<std::string> started;
  std::vector<vvi::state_record> told;
};

inline vvi::event_log log_of(const std::string& text) {
  vvi::event_log log;
  std::string error;
  EXPECT_TRUE(vvi::event_log::parse(text, "log", log, error)) << error;
  return log;
}

// A controller on a loaded model, with the log given replayed.
struct controlled {
  explicit controlled(const std::string& model, const vvi::event_log& log = {}, vvi::state_record from = {},
                      vvi::controller_policy policy = {})
      : o(options_for(model)), c(o, jobs, view, from, policy) {
    if (!from.restarted) c.load_build(built(model), log), c.poll(0);
  }
  void run(const command& cmd) {
    c.submit(cmd);
    c.poll(0);
  }
  void run(const std::string& line) {
    bool found = false;
    command cmd;
    std::string error;
    ASSERT_TRUE(vvi::parse_command_line(line, found, cmd, error)) << error;
    run(cmd);
  }
  // A build of the model's file, as the file watch asks for it.
  void reload() {
    c.submit(command::of(command::reload));
    for (int i = 0; i < 6000 && (c.building() || !c.idle()); ++i) {
      c.poll(0);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  std::string exported(const std::string& name) {
    std::string path = test_files::scratch_dir() + name;
    command e = command::with_path(command::export_mesh, path);
    e.name = "S";
    run(e);
    return test_files::slurp(path);
  }
  vvi::options o;
  recording_view view;
  recording_jobs jobs{view};
  vvi::model_controller c;
};

//! The line of a state model that holds `needle` (0: none).
inline int line_in_model(const std::string& model, const std::string& needle) {
  std::istringstream lines(test_files::slurp(state_models + model));
  int n = 1;
  for (std::string line; std::getline(lines, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

inline int vertices_in(const std::string& vvm) {
  int n = 0;
  for (std::size_t at = vvm.find("<v "); at != std::string::npos; at = vvm.find("<v ", at + 1)) ++n;
  return n;
}

}  // namespace controller_harness
