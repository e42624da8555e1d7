// One model's life, the same in the viewer and in batch mode: build (or
// find in the cache) → load a fresh instance → start → step → end → rewind
// or reload → close. The settings a model is built and loaded with are made
// here, once, from the command line.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "compile/model_build.hpp"
#include "runner/parameters.hpp"
#include "runner/session.hpp"

namespace vvi {

build_settings build_settings_for(const options& o, bool force = false);
session_settings session_settings_for(const options& o);

class model_runner {
 public:
  explicit model_runner(const options& o);

  //! Translates and compiles, or finds the build in the cache. It does not
  //! touch the running model, so it may run beside it on another thread.
  //! As usual; an edit's quick build where one can be made; the optimised
  //! build behind a quick one (compile/model_build.hpp: quick, in_background).
  //! `stop`: once set, the build stops (build_settings::cancel).
  enum class build_kind { usual, quick_first, behind_quick };
  build_result build(bool force, std::function<void()> compiling = {}, build_kind kind = build_kind::usual,
                     const std::atomic<bool>* stop = nullptr) const;

  //! A fresh instance of a plugin: loaded (every global initialised anew),
  //! started, then stepped `steps` times so a reload comes back to where the
  //! user was. It replaces the running model once its start worked (the old
  //! one's close block runs then); when loading or start fail, the running
  //! model stays and false is returned. A step that fails on the way leaves
  //! the new model at the step before, with error() set.
  //! With `resume` (a checkpoint file), the fresh instance takes the
  //! checkpoint's state instead of running start, and the user's parameter
  //! values after it; a checkpoint that cannot be read, or is of another
  //! program, fails the load as start does.
  bool load(const std::string& plugin_path, unsigned steps = 0, const std::string& resume = "");
  //! The same plugin again, from a fresh start.
  bool rewind(unsigned steps = 0) { return load(plugin_, steps); }
  bool step();
  bool end();
  bool reread();
  //! The program's action of this name, or its pick block with the vertex
  //! of this label: supervised and reported like a step (error() names the
  //! .vvp line), without advancing the step count.
  bool run_action(const std::string& name);
  bool run_pick(unsigned label);
  //! Runs the close block and unloads the model.
  void close();

  session* model() const { return model_.get(); }
  const std::string& plugin_path() const { return plugin_; }
  //! The last error (one message naming the .vvp line), or empty.
  const std::string& error() const { return error_; }
  void clear_error() { error_.clear(); }
  const options& opts() const { return o_; }

  //! The longest face orbit drawn or exported: --max-face, else the
  //! program's proxy.max_face (0: no limit).
  std::size_t max_face() const;
  //! The polygons of the chosen global meshes (--mesh: one, several, or by
  //! default the first), with the numeric vertex property value_field per
  //! vertex when asked; "" or the error. Valid until the next call.
  std::string geometry(vv_geometry& out, const std::string& value_field = "") const;
  //! A vertex by label: its properties, neighbourhood and records (text);
  //! "" or the error.
  std::string describe_vertex(unsigned label, std::string& text) const;
  //! The files the model's file objects read (for watching them).
  std::vector<std::string> file_objects() const;
  //! Writes the model's whole state to a checkpoint file; "" or the error.
  std::string save_checkpoint(const std::string& path) const;
  //! Writes the chosen meshes to a file (the format by its extension),
  //! through runner/output_file.hpp.
  std::string export_to(const std::string& path) const;
  std::string export_to(const std::string& path, const std::vector<std::string>& meshes) const;

  //! Sets a parameter of the running model and keeps the value for every
  //! fresh instance (rewind, reload); "" or why not.
  std::string set_parameter(const std::string& name, const std::string& text);
  //! The values the user gave (--set, set_parameter), kept across reloads.
  const std::vector<parameter_setting>& parameter_settings() const { return settings_; }
  //! The values the next fresh instance starts with instead (an event
  //! log's: control/event_log.hpp).
  void use_settings(std::vector<parameter_setting> settings) { settings_ = std::move(settings); }

  //! Set from another thread to end a run-up (load with steps) between steps.
  std::atomic<bool> cancel{false};

 private:
  //! Writes the meshes to exactly this path (export_to's temporary).
  std::string write_meshes(const std::string& path, const std::vector<std::string>& names) const;

  options o_;
  std::unique_ptr<session> model_;
  std::string plugin_;
  std::string error_;
  std::vector<parameter_setting> settings_;
};

}  // namespace vvi
