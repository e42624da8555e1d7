// The letter and digit keys the viewer takes for itself, in one list that
// the viewer dispatches from and vvc reads: an action's key (`action "Grow"
// key 'g'`) must not be one of them. A letter is the key whatever the case
// (Shift is not part of it). The viewer's other keys (space, arrows, + and
// -, Home, Escape, Ctrl+Q) are no letter or digit, so no action can take them.
#pragma once

#include <cctype>

namespace vv::model {

//! What a viewer key does.
enum class viewer_command { run, animate_or_stop, rewind, end, fit, screenshot };

struct viewer_key {
  char key;                //!< a lowercase letter or a digit
  viewer_command command;
  const char* does;        //!< in the words of docs/interpreter.md, for messages
};

inline constexpr viewer_key viewer_keys[] = {
    {'r', viewer_command::run, "run"},
    {'a', viewer_command::animate_or_stop, "animate / stop"},
    {'w', viewer_command::rewind, "rewind"},
    {'e', viewer_command::end, "end"},
    {'f', viewer_command::fit, "fit the view"},
    {'s', viewer_command::screenshot, "screenshot"},
};

//! The viewer's key for this character (either case), or null.
inline const viewer_key* find_viewer_key(char c) {
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const viewer_key& k : viewer_keys)
    if (k.key == lower) return &k;
  return nullptr;
}

}  // namespace vv::model
