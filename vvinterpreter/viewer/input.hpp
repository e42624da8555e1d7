// The mouse and the keys. Keys give commands: the viewer's letter keys are
// vv::model::viewer_keys (the list vvc checks actions' keys against), its
// other keys a table in input.cpp, and any other letter or digit runs the
// model's action with that key. A click gives a command too: Ctrl+click
// inspects the vertex under the cursor, Shift+click runs the model's pick
// block on it (a click: pressed and released without moving; a Shift+drag
// pans). Drags and the wheel move the camera directly.
#pragma once

#include "viewer/gl_window.hpp"

namespace vvi {

class model_controller;
class window_view;

//! Where the scene is drawn in the window: right of the panel when that
//! leaves it room enough (else the panel, which folds away, floats over
//! it), and left of the colour bar's strip.
struct scene_layout {
  float panel_right = 0;  //!< where the open panel ends, in window pixels
  double bar_strip = 0;   //!< the colour bar's strip, as a fraction of the window's width
  struct area {
    int left, width;
  };
  area in_window(int w) const;
};

class viewer_input : public input_handler {
 public:
  viewer_input(gl_window& w, model_controller& c, window_view& v, const scene_layout& layout)
      : window_(w), controller_(c), view_(v), layout_(layout) {}

  void on_button(int button, int action, int mods) override;
  void on_move(double x, double y) override;
  void on_scroll(double dy) override;
  void on_key(int key, int action, int mods) override;

 private:
  //! The label of the vertex under the cursor (0: none).
  unsigned label_under_cursor() const;

  gl_window& window_;
  model_controller& controller_;
  window_view& view_;
  const scene_layout& layout_;
  enum { none, rotating, panning } dragging_ = none;
  bool shift_click_ = false;  // Shift pressed on the left button, not moved yet
  double mouse_x_ = 0, mouse_y_ = 0, pressed_x_ = 0, pressed_y_ = 0;
};

}  // namespace vvi
