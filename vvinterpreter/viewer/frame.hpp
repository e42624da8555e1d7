// One frame of the viewer: the controller and the script move on, the
// panel is drawn (its commands go to the controller), then the scene
// beside it, the pictures asked for, and the window's part of the state
// record.
#pragma once

#include "control/model_controller.hpp"
#include "control/script_player.hpp"
#include "viewer/function_editor.hpp"
#include "viewer/gl_window.hpp"
#include "viewer/input.hpp"
#include "viewer/panel.hpp"
#include "viewer/window_view.hpp"

namespace vvi {

struct viewer_parts {
  gl_window& window;
  model_controller& controller;
  window_view& view;
  script_player& script;
  scene_layout& layout;
  function_editor& editor;
};

//! Seconds on a steady clock.
double now_seconds();

//! What the panel shows, from the controller and the view.
panel_state panel_state_of(const viewer_parts& v);

void draw_one_frame(viewer_parts& v);

}  // namespace vvi
