// One viewer process: the window, the model controller with the worker
// thread its model's code runs on, the script, and the frame loop.
#include "viewer/viewer.hpp"

#include <unistd.h>

#include <cstdio>

#include "app/files.hpp"
#include "control/command_text.hpp"
#include "control/model_worker.hpp"
#include "viewer/frame.hpp"

namespace vvi {

namespace {

// The --script commands; false (said on standard error) when it does not read.
bool read_script(const options& o, std::vector<command>& out) {
  if (o.script.empty()) return true;
  std::optional<std::string> text = read_file(o.script);
  std::string error;
  if (!text) error = o.script + ": cannot read the script";
  else out = parse_commands(*text, o.script, error);
  if (error.empty()) return true;
  std::fprintf(stderr, "vvinterpreter: %s\n", error.c_str());
  return false;
}

}  // namespace

int run_viewer_window(const options& o, const state_record& from) {
  gl_window window;
  if (!window.open("vv - " + o.model, from.view.window)) return 1;
  std::vector<command> script;
  if (!read_script(o, script)) {
    window.close();
    return 1;
  }
  window_view view(o, from);
  model_worker worker;  // outlives the controller, which runs its jobs on it
  model_controller controller(o, worker, view, from);
  view.attach(controller);
  script_player player(script, from.script_pos);
  scene_layout layout;
  function_editor editor;
  viewer_input input(window, controller, view, layout);
  window.set_input(&input);
  viewer_parts parts{window, controller, view, player, layout, editor};
  // The frame loop sleeps while a job or a build runs; their ends wake it.
  worker.job_ended().connect(gl_window::wake);
  controller.build_ended().connect(gl_window::wake);
  view.watch().saved().connect(gl_window::wake);  // a save, at once

  controller.set_up();
  controller.submit(command::of(command::reload));  // the first build
  while (!window.should_close()) draw_one_frame(parts);
  controller.set_quitting();  // whatever happens now, no restart
  worker.job_ended().disconnect();  // no wake after the window has gone
  controller.build_ended().disconnect();
  view.watch().saved().disconnect();
  if (controller.busy()) {  // closed while the model runs: it cannot be closed cleanly
    std::fflush(nullptr);
    _exit(0);
  }
  // A movie being recorded keeps the frames it has.
  if (std::string e = controller.finish_recording(); !e.empty()) std::fprintf(stderr, "vvinterpreter: %s\n", e.c_str());
  window.set_input(nullptr);
  view.scene().release();
  controller.close_model();
  window.close();
  return 0;
}

}  // namespace vvi
