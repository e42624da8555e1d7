// The C++ compiler's messages about a model, told in .vvp terms. The
// compiler knows .vvp lines (from #line) but counts columns in the
// generated line, and shows the .vvp line with a caret under that wrong
// column. Here each message about a .vvp line gets the .vvp column when the
// token at the compiler's column can be found on the .vvp line (else no
// column at all), and the .vvp line with a caret, as vvc prints its own.
#pragma once

#include <string>

namespace vvi {

//! Keeps the compiler's lines about the model's own files (.vvp and user
//! headers), dropping those inside vvlib and the system's headers, and
//! rewrites .vvp locations as above. generated_cpp: the C++ compiled.
std::string compiler_messages(const std::string& output, const std::string& vvlib_dir,
                              const std::string& generated_cpp);

}  // namespace vvi
