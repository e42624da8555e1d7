// The viewer's control panel (Dear ImGui): the model's state in, commands
// out (control/command.hpp), which the viewer gives its model controller.
//
// Its layout: the model's state and buttons, then the picked vertex (when
// there is one: near the top, so a pick is always in view), then the
// sections Actions, Parameters, Plots and Display, each folding away. The panel is
// never taller than the window; what does not fit scrolls.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "control/command.hpp"
#include "control/model_facts.hpp"
#include "render/scene.hpp"
#include "runner/mesh_counts.hpp"

namespace vvi {

struct panel_state {
  std::string model;
  std::string status;  // "running", "compiling ...", ...
  unsigned steps = 0;
  unsigned run_steps = 0;  // proxy.steps
  double last_step_ms = 0;
  std::vector<std::pair<std::string, std::size_t>> meshes;  // name, vertices
  bool animating = false;
  bool can_animate = true;  // !proxy.no_animate
  bool has_model = false;
  bool busy = false;        // the model's code is running
  std::string running;      // "step 3 running for 2.1 s", once a job runs long
  bool replay = true;       // reloads and restarts run the model again to its step
  std::string error;
  std::string warnings;
  std::string message;  // the last thing done ("wrote shot.png")

  std::vector<parameter_view> parameters;
  bool rewind_on_change = false;  // a parameter change re-runs from start to the step
  std::vector<std::string> recording;  // the series being recorded ("FILE every K steps")
  std::vector<plot_view> plots;
  display_style style;
  bool auto_fit = true;
  std::string color_by;                  // "" : plain
  std::vector<std::string> numeric_fields;  // what colour-by offers
  bool has_values = false;
  double value_min = 0, value_max = 0;
  mesh_counts counts;
  std::string picked;  // the picked vertex described, or ""
  unsigned picked_label = 0;  // a new label opens the inspector again
  std::vector<std::string> file_objects;  // files the model reads, reread on save
  std::vector<action_view> actions;       // the program's, a button each
  std::string last_checkpoint;            // the last one saved here: what Resume offers
};

struct panel_actions {
  //! What the user asked for, in order. A screenshot or a session saved
  //! has no file name yet (the viewer gives the next free one).
  std::vector<command> commands;
  float panel_right = 0;       // where the panel ends, in window pixels
  bool panel_collapsed = false;
  void add(command c) { commands.push_back(std::move(c)); }
};

//! The sections below the model's controls (viewer/panel_sections.cpp).
void draw_actions(const panel_state& s, panel_actions& a);
void draw_inspector(const panel_state& s, panel_actions& a);
void draw_parameters(const panel_state& s, panel_actions& a);
void draw_plots(const panel_state& s);
void draw_display(const panel_state& s, panel_actions& a);
//! The Record button beside the model's buttons, with its settings in a
//! popup; Stop recording while it records.
void draw_record(const panel_state& s, panel_actions& a);

//! Draws the panel; the first window of the frame (when its content
//! changed size, the frame is laid out again: see panel.cpp).
panel_actions draw_panel(const panel_state& s);

}  // namespace vvi
