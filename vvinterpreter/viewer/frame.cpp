#include "viewer/frame.hpp"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace vvi {

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

panel_state panel_state_of(const viewer_parts& v) {
  const model_controller& c = v.controller;
  const model_facts& f = c.facts();
  const scene_view& scene = v.view.scene();
  panel_state s;
  s.model = c.runner().opts().model;
  s.status = c.status();
  s.has_model = f.loaded;
  s.busy = c.busy();
  if (s.busy && c.job_seconds() >= long_job_seconds) {
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.1f", c.job_seconds());
    s.running = c.job_what() + " running for " + secs + " s";
  }
  // The model as the last job left it, also while the next one runs.
  s.steps = f.steps;
  s.last_step_ms = f.last_step_ms;
  s.run_steps = f.run_steps;
  s.can_animate = f.can_animate;
  s.meshes = f.meshes;
  s.parameters = f.parameters;
  s.plots = f.plots;
  s.file_objects = f.file_objects;
  s.actions = f.actions;
  s.animating = c.animating();
  s.replay = c.record().replay;
  s.rewind_on_change = c.record().rewind_on_change;
  s.recording = c.recorded_files();
  s.error = v.view.error();
  s.warnings = c.warnings();
  s.message = v.view.message();
  s.style = scene.style();
  s.auto_fit = scene.auto_fit();
  s.color_by = scene.color_by();
  s.numeric_fields = scene.inspected().numeric_fields();
  s.has_values = scene.drawing().has_values();
  s.value_min = scene.drawing().value_min();
  s.value_max = scene.drawing().value_max();
  s.counts = scene.inspected().counts();
  s.picked = scene.inspected().text();
  s.picked_label = scene.inspected().picked_label();
  s.last_checkpoint = v.view.last_checkpoint_name();
  return s;
}

namespace {

// The panel's commands, with the file names a button cannot give.
void give(viewer_parts& v, std::vector<command> commands) {
  for (command& c : commands) {
    if (c.kind == command::screenshot && c.path.empty()) c.path = v.view.next_screenshot_name();
    if (c.kind == command::save_session && c.path.empty()) c.path = v.view.next_session_name();
    if (c.kind == command::checkpoint && c.path.empty()) c.path = v.view.next_checkpoint_name();
    v.controller.submit(c);
  }
}

// The scene, beside the panel; the pictures asked for frame the model in
// the whole picture. While the model's code runs, its state is not to be
// read: the last drawing is drawn, without the model's render blocks.
void draw_scene(viewer_parts& v, int w, int h) {
  model_controller& c = v.controller;
  scene_view& scene = v.view.scene();
  session* model = c.busy() ? nullptr : c.runner().model();
  v.layout.bar_strip = double(scene.bar_strip(model, w)) / w;
  if (!c.busy()) {
    std::vector<scene_shot> shots = v.view.take_scene_shots();
    if (!shots.empty()) scene.draw(model, w, h, 0);
    for (const scene_shot& shot : shots) v.view.save_picture(shot, w, h);
    if (!shots.empty()) v.view.pictures_taken();
  }
  int window_w = 0, window_h = 0;
  v.window.size(window_w, window_h);
  int left = window_w > 0 ? static_cast<int>(std::lround(double(v.layout.in_window(window_w).left) * w / window_w)) : 0;
  scene.draw(model, w, h, left);
  v.view.drawn(!c.busy());
}

}  // namespace

void draw_one_frame(viewer_parts& v) {
  model_controller& c = v.controller;
  // No frame until there is something to show or do: a frame drawn in
  // software takes a core from the model and the compiler. Input, and the
  // end of a job or a build, wake the loop at once.
  // The file watch looks on time too: a wake a moment early would skip a
  // look and leave a save unseen for another quarter of a second.
  double t = now_seconds();
  bool script_goes_on = !v.script.done() && c.idle();
  v.window.wait_events(script_goes_on ? 0 : std::min(c.seconds_until_due(t), v.view.watch().seconds_until_look(t)));
  t = now_seconds();
  v.view.watch().check(t, c);
  c.poll(t);
  v.script.feed(c);
  c.poll(t);

  // The panel first (Dear ImGui draws nothing yet): the scene is placed
  // beside the panel as it is on this frame.
  ImGui_ImplOpenGL2_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  panel_actions a = draw_panel(panel_state_of(v));
  v.layout.panel_right = a.panel_collapsed ? 0 : a.panel_right;
  // The function editor's Save writes the file; the file watch then has
  // the model reread it.
  std::string said, error;
  v.editor.draw(c.facts().file_objects, said, error);
  if (!said.empty()) v.view.say(said);
  if (!error.empty()) v.view.show_error(error, error);

  int w = 0, h = 0;
  v.window.framebuffer_size(w, h);
  if (w > 0 && h > 0) draw_scene(v, w, h);
  ImGui::Render();
  ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
  std::string window_shot = v.view.take_window_shot();
  if (!window_shot.empty() && w > 0 && h > 0) v.view.save_picture({window_shot}, w, h);
  v.window.swap();
  give(v, std::move(a.commands));
  int place[4];
  v.window.place(place);
  c.update_view(v.view.record(place));
  if (v.view.quit_asked()) v.window.request_close();
}

}  // namespace vvi
