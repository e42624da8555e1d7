// The C++ compiler's messages about a model, told in .vvp terms. The
// compiler knows .vvp lines (from #line) but counts columns in the
// generated line, and shows the .vvp line with a caret under that wrong
// column. Here each message about a .vvp line gets the .vvp column when the
// token at the compiler's column can be found on the .vvp line (else no
// column at all), and the .vvp line with a caret, as vvc prints its own.
// Quotes are plain ASCII, and a member missing from a property block is
// named as the program names it (property_messages.hpp).
#pragma once

#include <string>

#include "compile/property_messages.hpp"

namespace vvi {

//! What the messages are read against.
struct message_sources {
  std::string vvlib_dir;      // messages about files in it (and in /usr) are dropped
  std::string generated_cpp;  // the C++ compiled
  property_fields fields;     // the program's property blocks
};

//! Keeps the compiler's lines about the model's own files (.vvp and user
//! headers), dropping those inside vvlib and the system's headers, and
//! rewrites .vvp locations as above. Any text is accepted: a line or column
//! number that does not fit an int is left as the compiler wrote it.
std::string compiler_messages(const std::string& output, const message_sources& sources);

//! The compiler's typographic quotes (U+2018/2019, U+201C/201D) as ASCII ones.
std::string plain_quotes(std::string text);

}  // namespace vvi
