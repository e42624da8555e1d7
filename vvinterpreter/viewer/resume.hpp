// What a viewer that crashed or was stopped comes back with. The viewer
// process tells its supervisor its state as it goes ("state ..." lines on
// the report pipe); when the process dies, the supervisor makes a resume
// from the last state and the crash, and starts a new viewer with it: same
// window place, camera, script position and model step, and the crash shown
// in the panel.
#pragma once

#include <string>

namespace vvi {

//! The viewer's exit code that asks its supervisor for a restart (Stop).
constexpr int viewer_restart_code = 75;

struct viewer_resume {
  bool restarted = false;
  std::string good_plugin;       //!< the model that ran before
  unsigned good_steps = 0;       //!< its completed steps (the restart runs it again to there)
  std::string bad_plugin;        //!< crashed while loading or starting: not loaded again as it is
  std::string no_render_plugin;  //!< crashed while drawing: its render blocks are not called
  std::string camera;            //!< camera::save()
  int window[4] = {0, 0, 0, 0};  //!< x y width height (width 0: unknown)
  std::size_t script_pos = 0;
  int screenshots = 0;
  bool replay = true;            //!< run a reloaded or restarted model again to the step
  std::string error;             //!< what happened, for the panel
  std::string note;              //!< how it was restarted
};

//! The viewer's state as its supervisor last heard it.
class viewer_state {
 public:
  //! One "state ..." line from the viewer.
  void hear(const std::string& line);

  bool up = false;               //!< the window opened
  bool quitting = false;         //!< the user closed it: no restart
  std::string model_plugin, trying_plugin;
  unsigned model_steps = 0;
  std::string camera;
  int window[4] = {0, 0, 0, 0};
  std::size_t script_pos = 0;
  int screenshots = 0;
  bool replay = true;
  std::string stopped;           //!< "step 3 was stopped after 2.5 s" when the user pressed Stop
  std::string stopped_activity;  //!< what ran when stopped ("step", "start", "replay", ...)
};

//! Sends a state line to the supervisor (runner/fault_guard.hpp's pipe).
void tell_supervisor(const std::string& key, const std::string& value);

}  // namespace vvi
