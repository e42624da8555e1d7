// A running model: a loaded plugin, its step count and timing, and the
// last error. Errors never throw out of here: each call says whether it
// worked and keeps the message (which names the .vvp file and line).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runner/plugin.hpp"

namespace vvi {

struct session_settings {
  std::string model;      // the .vvp (or plugin) the user named, for messages
  std::string model_dir;  // relative paths in the program resolve against it
  std::uint64_t seed = 0;
  bool strict = false;    // reading a never-synchronised old state is an error
  bool check = false;     // check the neighbourhoods after start and every step
  unsigned threads = 0;   // of a parallel forall (0: the machine's cores)
};

class session {
 public:
  static std::unique_ptr<session> load(const std::string& plugin_path, const session_settings& s,
                                       std::string& error);

  bool start();
  bool step();
  bool end();
  bool reread();
  //! Runs the program's action of this name, supervised and reported like
  //! a step (the error names its .vvp line and the action), without
  //! advancing the step count; an unknown name is an error naming it.
  bool run_action(const std::string& name);
  //! Runs the program's pick block with the vertex of this label, like an
  //! action; a model without a pick block, or a label no global mesh
  //! holds, is an error naming it.
  bool run_pick(unsigned label);
  //! The render blocks (call with the GL context current); true when the
  //! model has no such block.
  bool render_init();
  bool render();
  bool render_screen();
  //! Drawing is announced to the supervisor (timed, sampled) like the
  //! other blocks: for a single drawing (batch), not every frame.
  void announce_drawing(bool on) { announce_drawing_ = on; }
  //! Instead of start: the model's state from a checkpoint (its bytes),
  //! which was saved after `step` steps. False with the error set; the
  //! model is then half restored and must be unloaded.
  bool resume(const std::string& state, unsigned step);
  //! The model's whole state, for a checkpoint; "" or the error, which
  //! names every global the checkpoint cannot hold with its .vvp line.
  std::string save_state(std::string& out) const;
  //! Runs the close block (once); the plugin stays loaded until destruction.
  void close();
  //! A model that never started is unloaded without its close block.
  void skip_close() { closed_ = true; }
  ~session();

  unsigned steps_done() const { return steps_; }
  double last_step_ms() const { return last_step_ms_; }
  const std::string& error() const { return error_; }

  std::vector<const vv_mesh_entry*> meshes() const;
  //! A global mesh by name, or the first one when name is empty.
  const vv_mesh_entry* mesh(const std::string& name) const;
  //! What the program set in its proxy (steps, delay, view volume, ...).
  vv_run_settings run_settings() const;
  //! The series the program recorded with proxy.plot; the pointers in them
  //! stay valid until the model's code runs again.
  std::vector<vv_plot_series> plots() const;
  //! The program's actions, in source order.
  std::vector<const vv_action_entry*> actions() const;
  //! The action of this name, or null.
  const vv_action_entry* action(const std::string& name) const;
  //! The model's descriptor (model/abi.hpp).
  const vv_plugin& model() const { return plugin_->model(); }
  //! Whether the program has this block, e.g. has_block(&vv_plugin::render).
  bool has_block(plugin::block_fn vv_plugin::*block) const { return plugin_->model().*block != nullptr; }

 private:
  session(std::unique_ptr<plugin> p, std::string model, bool check)
      : plugin_(std::move(p)), model_(std::move(model)), check_(check) {}
  //! Runs a block as the named activity (runner/fault_guard.hpp).
  bool run(const char* block, plugin::block_fn fn, unsigned step = 0, bool announce = true);
  //! Runs an action or the pick block (`what` names it) between steps.
  template <class Call>
  bool run_between_steps(const std::string& what, Call call);
  //! --check: false with the error set when a neighbourhood is broken.
  bool check_neighbourhoods(const std::string& after);
  //! The message with the .vvp line of an error that came without one.
  std::string locate(const std::string& message) const;

  //! With no supervisor (--in-process, --debug), exit() inside a block is
  //! said here as the supervisor says it (an on_exit handler).
  static void say_exit_in_block(int status, void*);
  std::unique_ptr<plugin> plugin_;
  std::string model_;
  unsigned steps_ = 0;
  double last_step_ms_ = 0;
  std::string error_;
  bool closed_ = false;
  bool check_ = false;
  bool announce_drawing_ = false;
};

}  // namespace vvi
