#include "viewer/input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <model/viewer_keys.hpp>

#include "control/command_text.hpp"
#include "control/model_controller.hpp"
#include "viewer/window_view.hpp"

namespace vvi {

namespace {

// The viewer's keys that are no letter or digit, and the commands they
// give. Its letter keys are vv::model::viewer_keys, the list vvc checks
// actions' keys against.
struct key_binding {
  int key;
  const char* command;
};

const key_binding keys[] = {
    {GLFW_KEY_SPACE, "step"},
    {GLFW_KEY_HOME, "reset-view"},
    {GLFW_KEY_LEFT, "rotate -5 0"},
    {GLFW_KEY_RIGHT, "rotate 5 0"},
    {GLFW_KEY_UP, "rotate 0 -5"},
    {GLFW_KEY_DOWN, "rotate 0 5"},
    {GLFW_KEY_EQUAL, "zoom 1.15"},
    {GLFW_KEY_KP_ADD, "zoom 1.15"},
    {GLFW_KEY_MINUS, "zoom 0.8695652173913044"},
    {GLFW_KEY_KP_SUBTRACT, "zoom 0.8695652173913044"},
    {GLFW_KEY_ESCAPE, "stop"},  // a running step, or the animation
};

// What a letter key of the viewer does, as a command.
const char* command_of(vv::model::viewer_command k) {
  switch (k) {
    case vv::model::viewer_command::run: return "run";
    case vv::model::viewer_command::animate_or_stop: return "animate";
    case vv::model::viewer_command::rewind: return "rewind";
    case vv::model::viewer_command::end: return "end";
    case vv::model::viewer_command::fit: return "fit";
    case vv::model::viewer_command::screenshot: return "screenshot x";
  }
  return "";
}

// The letter or digit a key types (lowercase), or 0.
char key_character(int key) {
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return static_cast<char>('a' + (key - GLFW_KEY_A));
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return static_cast<char>('0' + (key - GLFW_KEY_0));
  return 0;
}

command parsed(const char* text) {
  bool found = false;
  command c;
  std::string error;
  parse_command_line(text, found, c, error);
  return c;
}

constexpr double click_slack = 3;  // pixels a click may move and stay a click

}  // namespace

scene_layout::area scene_layout::in_window(int w) const {
  int right = w - static_cast<int>(std::lround(bar_strip * w));
  int left = static_cast<int>(panel_right) + 6;
  if (right - left < std::max(300, w / 3)) left = 0;
  return {left, std::max(1, right - left)};
}

unsigned viewer_input::label_under_cursor() const {
  int w = 0, h = 0;
  window_.size(w, h);
  scene_layout::area scene = layout_.in_window(w);
  return view_.scene().label_at(mouse_x_ - scene.left, mouse_y_, scene.width, h);
}

void viewer_input::on_button(int button, int action, int mods) {
  if (ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
  window_.cursor(mouse_x_, mouse_y_);
  bool left = button == GLFW_MOUSE_BUTTON_LEFT;
  if (action == GLFW_PRESS && left && (mods & GLFW_MOD_CONTROL)) {
    controller_.submit(command::labelled(command::inspect, label_under_cursor()));
    return;
  }
  if (action == GLFW_PRESS) {
    dragging_ = left && !(mods & GLFW_MOD_SHIFT) ? rotating : panning;
    shift_click_ = left && (mods & GLFW_MOD_SHIFT);
    pressed_x_ = mouse_x_, pressed_y_ = mouse_y_;
    return;
  }
  // A Shift+click on a vertex of a model with a pick block (elsewhere it is
  // a pan that did not move).
  if (shift_click_ && left && controller_.facts().has_pick) {
    if (unsigned label = label_under_cursor()) controller_.submit(command::labelled(command::pick_action, label));
  }
  shift_click_ = false;
  dragging_ = none;
}

void viewer_input::on_move(double x, double y) {
  if (shift_click_ && std::hypot(x - pressed_x_, y - pressed_y_) > click_slack) shift_click_ = false;
  if (dragging_ != none) {
    int w = 0, h = 0;
    window_.size(w, h);
    if (dragging_ == rotating) view_.scene().drag_rotate(mouse_x_, mouse_y_, x, y, w, h);
    else view_.scene().pan(x - mouse_x_, y - mouse_y_, layout_.in_window(w).width, h);
  }
  mouse_x_ = x, mouse_y_ = y;
}

void viewer_input::on_scroll(double dy) {
  if (!ImGui::GetIO().WantCaptureMouse) view_.scene().zoom(dy > 0 ? 1.15 : 1 / 1.15);
}

void viewer_input::on_key(int key, int action, int mods) {
  if (ImGui::GetIO().WantCaptureKeyboard || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
  if (key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL)) return controller_.submit(command::of(command::quit));
  command c;
  if (char ch = key_character(key)) {
    if (const vv::model::viewer_key* k = vv::model::find_viewer_key(ch)) {
      c = parsed(command_of(k->command));
    } else {
      // The model's action with this key, if it has one.
      const std::vector<action_view>& actions = controller_.facts().actions;
      auto a = std::find_if(actions.begin(), actions.end(), [ch](const action_view& v) { return v.key == ch; });
      if (a == actions.end()) return;
      c = command::named(command::action, a->name);
    }
  } else {
    auto k = std::find_if(std::begin(keys), std::end(keys), [key](const key_binding& b) { return b.key == key; });
    if (k == std::end(keys)) return;
    c = parsed(k->command);
  }
  if (c.kind == command::screenshot) c.path = view_.next_screenshot_name();
  if (c.kind == command::animate && controller_.animating()) c = command::of(command::stop);
  controller_.submit(c);
}

}  // namespace vvi
