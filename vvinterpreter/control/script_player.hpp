// --script FILE: commands given to the model controller one at a time, each
// once the one before has finished (its steps, its build, its picture),
// so the interactive viewer can be driven, and tested, without a person.
// Two go on beside a running job: `wait` and `window-screenshot`; `stop`
// ends a job once it has run for half a second (as the Stop button does:
// the model restarts at its last good state).
//
// The position is part of the state record: it is told before the model
// runs what a command asked, so a window that comes back after a crash
// goes on after the command that crashed, never runs it again.
#pragma once

#include <string>
#include <vector>

#include "control/command.hpp"

namespace vvi {

class model_controller;

//! A job runs this long before the window shows it as running, with Stop.
constexpr double long_job_seconds = 0.5;

class script_player {
 public:
  script_player() = default;
  //! The commands, from `position` on (a restarted window's).
  script_player(std::vector<command> commands, std::size_t position)
      : commands_(std::move(commands)), position_(position) {}

  //! Gives the controller the commands it can take now.
  void feed(model_controller& c);
  bool done() const { return position_ >= commands_.size(); }
  std::size_t position() const { return position_; }

 private:
  std::vector<command> commands_;
  std::size_t position_ = 0;
};

}  // namespace vvi
