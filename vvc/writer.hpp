// Text output that follows the source's lines: a token from source line L
// goes on an output line the compiler also calls L (newlines, or a #line
// directive when the gap is large, the file changes or code was generated
// in between), so compiler errors and debuggers point at the .vvp file.
#pragma once

#include <string>
#include <string_view>

#include "token.hpp"

namespace vvc {

//! s as a C++ string literal (for paths in #line directives and generated code).
std::string cpp_string_literal(const std::string& s);

class writer {
 public:
  //! A source token, on its line, spaced as in the source.
  void token(const vvc::token& t);
  //! Generated text on the current line.
  void text(std::string_view s);
  //! Moves to the line of t without writing it (before generated text
  //! that stands for t: `forall` becomes `for`).
  void at(const vvc::token& t);
  //! Generated lines of their own: the next token re-synchronises.
  void lines(std::string_view s);
  //! Generated code whose compiler messages should not name a .vvp line:
  //! it is marked as a file of its own, "<vvc generated>".
  void generated(std::string_view s);
  //! A preprocessor line, alone on its line.
  void preproc(const vvc::token& t);

  const std::string& str() const { return out_; }

 private:
  void sync(const vvc::token& t);
  void newline();
  void separate(std::string_view next, bool space_before);

  std::string out_;
  const source_file* file_ = nullptr;  // nullptr: not synchronised
  int line_ = 0;
};

}  // namespace vvc
