// The command language: one command a line, as --script files, saved
// sessions and the event log write them. One table (command_text.cpp)
// gives each command's word, its arguments and what it does; the parser,
// the printer and the help are all read from it.
//
//   step 3                 # a word, then its arguments
//   action "Divide all"    # a word with spaces is quoted ("\"" and "\\" inside)
//   set rate=0.25          # a '#' that starts a word starts a comment
//
// Blank lines are skipped.
#pragma once

#include <string>
#include <vector>

#include "control/command.hpp"

namespace vvi {

//! Every command with its arguments and what it does, a line each.
std::string command_help();

//! The command on one line, or (empty line, comment) none; false with
//! `error` ("unknown command 'x'", ...) when the line is not a command.
bool parse_command_line(const std::string& line, bool& found, command& out, std::string& error);

//! The commands of a text (a script, a session); on a bad line, nothing
//! and error = "name:line: problem".
std::vector<command> parse_commands(const std::string& text, const std::string& name, std::string& error);

//! The command as a line of the language (no newline); parsing it gives
//! the same command.
std::string command_text(const command& c);

//! The word a command kind is written with ("step", "pick-action").
const char* command_word(command::kind_t k);

}  // namespace vvi
