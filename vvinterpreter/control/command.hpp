// One command, whoever gives it: a key, the panel, a --script line, batch's
// options or a saved session. The model controller (model_controller.hpp)
// is the one thing that carries commands out; their text form is the
// script language (command_text.hpp).
#pragma once

#include <string>

namespace vvi {

struct command {
  enum kind_t {
    // What changes the model. step, end, reread, set, action and
    // pick_action are its events: the event log keeps them.
    step, run, animate, stop, rewind, resume, end, reread, reload, recompile, set, action, pick_action,
    // Looking into it and writing it out.
    inspect, export_mesh, plots, save_params, save_session, checkpoint, record,
    // The view.
    screenshot, window_screenshot, fit, rotate, zoom, reset_view, show, color_by,
    // How the viewer goes on.
    replay, rewind_on_change, wait, quit
  };

  kind_t kind = step;
  unsigned long number = 1;  //!< step N, wait MS, inspect and pick-action LABEL (inspect 0: none), record K
  double x = 0, y = 0;       //!< rotate DX DY (degrees), zoom F
  //! set NAME=VALUE, action NAME, export MESH, color-by NAME ("" : none),
  //! show WHAT
  std::string name, value;
  std::string path;          //!< screenshot, window-screenshot, export, plots, save-session, checkpoint, resume, record
  bool on = true;            //!< show, replay, rewind-on-change, record (off: stop recording)
  unsigned digits = 0;       //!< record: the width {step} is padded to (0: the default, 5)
  int line = 0;              //!< where it was read (0: not from a file)

  //! A command without arguments (or with their defaults).
  static command of(kind_t k) {
    command c;
    c.kind = k;
    return c;
  }
  static command steps(unsigned long n) {
    command c = of(step);
    c.number = n;
    return c;
  }
  static command with_path(kind_t k, const std::string& path) {
    command c = of(k);
    c.path = path;
    return c;
  }
  static command named(kind_t k, const std::string& name, const std::string& value = "") {
    command c = of(k);
    c.name = name, c.value = value;
    return c;
  }
  static command labelled(kind_t k, unsigned long label) {
    command c = of(k);
    c.number = label;
    return c;
  }
  static command switched(kind_t k, const std::string& what, bool on) {
    command c = named(k, what);
    c.on = on;
    return c;
  }

  //! record K FILE, and record off.
  static command recording(unsigned long every, const std::string& file, unsigned digits = 0) {
    command c = with_path(record, file);
    c.number = every, c.digits = digits;
    return c;
  }
  static command record_off() {
    command c = of(record);
    c.on = false;
    return c;
  }

  //! The same command (its line aside).
  friend bool operator==(const command& a, const command& b) {
    return a.kind == b.kind && a.number == b.number && a.x == b.x && a.y == b.y && a.name == b.name &&
           a.value == b.value && a.path == b.path && a.on == b.on && a.digits == b.digits;
  }
  friend bool operator!=(const command& a, const command& b) { return !(a == b); }
};

//! The model's events: what the event log records and a session replays.
inline bool is_event(command::kind_t k) {
  return k == command::step || k == command::end || k == command::reread || k == command::set ||
         k == command::action || k == command::pick_action;
}

}  // namespace vvi
