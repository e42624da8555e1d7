// Tokens: views into the source text with their file, line and column.
#pragma once

#include <string_view>

#include "source.hpp"

namespace vvc {

enum class tok {
  identifier,  // also C++ keywords and vv words: meaning depends on place
  number,      // any C++ number (pp-number: hex, binary, separators, suffixes)
  string,      // "...", raw strings, with any prefix
  character,   // '...', with any prefix
  punct,       // C++ operators and punctuation
  preproc,     // a whole preprocessor line (continuations included)
  backtick,    // ` or U+2018: the old state of a vertex
  dollar,      // $: vertex property access
  at,          // @: path expressions
  eof,
};

struct token {
  tok kind = tok::eof;
  std::string_view text;
  const source_file* file = nullptr;
  int line = 0;
  int col = 0;
  bool space_before = false;  // whitespace or a comment precedes it
  bool line_start = false;    // first token on its line

  bool is(std::string_view s) const { return (kind == tok::punct || kind == tok::identifier) && text == s; }
  bool is_identifier() const { return kind == tok::identifier; }
  bool is_word(std::string_view s) const { return kind == tok::identifier && text == s; }
};

}  // namespace vvc
