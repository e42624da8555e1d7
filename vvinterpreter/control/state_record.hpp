// The viewer's state record: everything a viewer process that dies (a
// crash, a Stop) comes back with. The window process sends it to its
// supervisor whenever it changes, as one line on the report pipe, and
// always before it starts the model's code; the supervisor keeps the last
// one and starts the next window from it (control/restart.hpp).
#pragma once

#include <string>

#include "control/event_log.hpp"

namespace vvi {

//! The viewer's exit code that asks its supervisor for a restart (Stop).
constexpr int viewer_restart_code = 75;

//! How the window shows the model.
struct view_record {
  std::string camera;            //!< camera::save()
  int window[4] = {0, 0, 0, 0};  //!< x y width height (width 0: not known)
  bool faces = true, edges = true, points = false, flat = false, back_faces = true, auto_hide_edges = true;
  bool auto_fit = true;
  std::string color_by;
  unsigned picked = 0;           //!< the inspected vertex's label (0: none)
  int screenshots = 0;           //!< vv_screenshot_NNN.png written so far

  friend bool operator==(const view_record& a, const view_record& b);
  friend bool operator!=(const view_record& a, const view_record& b) { return !(a == b); }
};

struct state_record {
  // ---- the model ----
  std::string plugin;            //!< the model, at the state `log` replayed gives
  event_log log;
  std::string trying;            //!< a new build being loaded and replayed: not good yet
  long replaying = -1;           //!< the event of `log` being replayed (-1: none)
  std::string bad_plugin;        //!< crashed while loading or starting: not loaded again as it is
  std::string no_render_plugin;  //!< crashed while drawing: its render blocks are not called
  bool replay = true;            //!< reloads, restarts and errors replay the log (else: step 0)
  bool rewind_on_change = false; //!< a parameter change runs the model again from start
  // ---- the window ----
  view_record view;
  std::size_t script_pos = 0;    //!< --script commands given so far
  // ---- the process ----
  bool up = false;               //!< the window opened
  bool quitting = false;         //!< the user closed it: no restart
  std::string stopped;           //!< "step 3 was stopped after 2.5 s" (Stop)
  std::string stopped_activity;  //!< what ran when stopped ("step", "loading", ...)
  // ---- after a restart ----
  bool restarted = false;
  std::string error;             //!< what happened, for the panel
  std::string note;              //!< how it came back
};

//! The record as one line ("state key=value ...", values %-escaped).
std::string record_line(const state_record& r);
//! Reads a record_line; false (out unchanged) when the line is not one.
bool read_record_line(const std::string& line, state_record& out);

}  // namespace vvi
