// The lexer: C++ tokens plus vv's ` (and U+2018), $ and @. Comments are
// dropped; preprocessor lines are kept whole, except that `#include` of a
// .vvp file is replaced by that file's tokens (it is translated too).
#pragma once

#include <vector>

#include "diagnostics.hpp"
#include "token.hpp"

namespace vvc {

//! The tokens of file, ending with one eof token.
std::vector<token> lex(const source_file& file, source_set& sources, diagnostics& diag);

}  // namespace vvc
