// What the model controller needs from whatever shows the model: the
// viewer's window, batch mode, or a test. The controller calls it on its
// own thread, never while the model's code runs, except compiling().
#pragma once

#include <string>

#include "compile/model_build.hpp"
#include "control/command.hpp"
#include "control/state_record.hpp"

namespace vvi {

//! What a job did to the model.
struct model_change {
  enum kind_t {
    loaded,   //!< a fresh instance replaced the model (load, reload, rewind, restore), replayed
    stepped,  //!< a step
    changed,  //!< end, an action, a pick, a reread, a parameter
  } kind = changed;
};

class controller_view {
 public:
  virtual ~controller_view() = default;

  //! Whether what the last job left has been shown: the next job waits
  //! for it (the window draws each state once, and records it as a frame
  //! when the model asks for frames).
  virtual bool caught_up() const { return true; }
  //! The model's state changed; it is idle now.
  virtual void model_changed(const model_change&) {}
  //! A command of the view (inspect, screenshot, window-screenshot, fit,
  //! rotate, zoom, reset-view, show, color-by, quit): false when it cannot
  //! be carried out yet (it is asked again at the next poll).
  virtual bool view(const command&) { return true; }

  //! A picture of a recorded series (control/recording.hpp) of the model
  //! at `step`: `file` is a .png to write, or a movie (.mp4) that gets the
  //! frame. "" or the error; a view that takes its pictures later reports
  //! their errors itself.
  virtual std::string record_picture(const std::string& file, unsigned long) {
    return "record " + file + ": this view takes no pictures";
  }
  //! The movie `file` gets no more frames: put in place (`keep`) or
  //! dropped; "" or the error.
  virtual std::string end_movie(const std::string&, bool) { return ""; }

  //! What was done ("reloaded model.vvp"), and files written.
  virtual void say(const std::string&) {}
  virtual void wrote(const std::string& path) { say("wrote " + path); }
  //! An error: `shown` for the panel (may span lines), `line` for the log.
  virtual void show_error(const std::string& shown, const std::string& line) = 0;
  virtual void clear_error() {}

  //! The state record changed: the supervisor must have it before the
  //! model's code runs again.
  virtual void record_changed(const state_record&) {}
  //! Stop: the running job cannot be cut short in this process; the
  //! window process ends and its supervisor starts it again.
  virtual void abandon_job() {}

  //! A build is starting (the files it reads are as they are now).
  virtual void build_started() {}
  //! Called on the build's thread once the sources are read.
  virtual void compiling() {}
  virtual void build_finished(const build_result&) {}
};

}  // namespace vvi
