// The viewer's control panel (Dear ImGui): buttons in, actions out. It
// only shows state; the viewer decides what the actions do.
//
// Its layout: the model's state and buttons, then the picked vertex (when
// there is one: near the top, so a pick is always in view), then the
// sections Parameters, Plots and Display, each folding away. The panel is
// never taller than the window; what does not fit scrolls.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/scene.hpp"
#include "runner/mesh_counts.hpp"

namespace vvi {

//! A parameter as the panel shows it.
struct parameter_view {
  std::string name, type, text;  //!< text: the value as it reads back exactly
  double number = 0;             //!< the value (bool: 0 or 1)
  bool has_range = false;
  double lo = 0, hi = 0;
  int line = 0;
};

//! A proxy.plot series: its values in the order of the steps recorded.
struct plot_view {
  std::string name;
  std::vector<float> values;
  unsigned first_step = 0, last_step = 0;
  double last = 0;
};

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
};

struct panel_actions {
  bool step = false, run = false, animate = false, stop = false, rewind = false, end = false;
  bool reread = false, recompile = false, fit = false, screenshot = false;
  bool toggle_replay = false;
  std::vector<std::pair<std::string, std::string>> set_parameters;  // name, text
  bool save_parameters = false, toggle_rewind_on_change = false;
  bool style_changed = false;
  display_style style;           // valid when style_changed
  bool toggle_auto_fit = false;
  bool color_by_changed = false;
  std::string color_by;          // valid when color_by_changed
  bool clear_pick = false;
  float panel_right = 0;       // where the panel ends, in window pixels
  bool panel_collapsed = false;
};

//! The sections below the model's controls (viewer/panel_sections.cpp).
void draw_inspector(const panel_state& s, panel_actions& a);
void draw_parameters(const panel_state& s, panel_actions& a);
void draw_plots(const panel_state& s);
void draw_display(const panel_state& s, panel_actions& a);

//! Draws the panel; the first window of the frame (when its content
//! changed size, the frame is laid out again: see panel.cpp).
panel_actions draw_panel(const panel_state& s);

}  // namespace vvi
