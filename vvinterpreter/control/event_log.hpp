// The event log (LANGUAGE.md §12): everything that changed the running
// model since it started, in order — steps, end, actions, picks with their
// vertex, parameter changes, rereads — and the parameter values it started
// with. Replaying it on a fresh instance gives the same state: that is how
// a reload, a restart and a restore after an error come back to where the
// user was, and what a saved session holds.
//
// Its text is the command language (command_text.hpp):
//
//   set spacing=3        the values the model started with, before its
//   rewind               start block (when there are any), or after the
//                        checkpoint it went on from ("resume FILE" in
//                        place of "rewind"), then
//   step 2               its events
//   pick-action 17
//   end
#pragma once

#include <string>
#include <vector>

#include "control/command.hpp"
#include "runner/parameters.hpp"

namespace vvi {

class event_log {
 public:
  //! The parameter values the model started with (applied before start).
  std::vector<parameter_setting> initial;
  //! What changed it since, in order (is_event commands only).
  std::vector<command> events;
  //! The checkpoint the model went on from instead of its start ("" : it
  //! started); `initial` then applies after the checkpoint's state.
  std::string resumed_from = "";

  //! Appends an event; steps right after steps are one event ("step 5").
  void append(const command& event);
  //! The steps its events run.
  unsigned long steps() const;
  //! The steps the events before `index` run.
  unsigned long steps_before(std::size_t index) const;
  //! The events before `index` only, and `extra_steps` steps of the event
  //! at `index` when it is a step (a replay that stopped inside it).
  event_log up_to(std::size_t index, unsigned long extra_steps = 0) const;
  //! The parameter values after all its events: a fresh start with them
  //! has every parameter as the model has it now.
  std::vector<parameter_setting> settings_after() const;

  //! The log in the command language, a line each.
  std::string text() const;
  //! Reads the command language: a `rewind` starts the log again with the
  //! values set so far, a `resume FILE` too, from the checkpoint. False with error "name:line: problem" on a line
  //! that is not a command, or not an event or a rewind.
  static bool parse(const std::string& text, const std::string& name, event_log& out, std::string& error);

  friend bool operator==(const event_log& a, const event_log& b);
  friend bool operator!=(const event_log& a, const event_log& b) { return !(a == b); }
};

//! settings with NAME's value given (replaced, or added at the end).
void set_setting(std::vector<parameter_setting>& settings, const std::string& name, const std::string& text);

}  // namespace vvi
