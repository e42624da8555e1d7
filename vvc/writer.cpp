#include "writer.hpp"

#include <cctype>

namespace vvc {

namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string cpp_string_literal(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

void writer::newline() {
  out_ += '\n';
  ++line_;
}

void writer::sync(const vvc::token& t) {
  constexpr int max_blank_lines = 8;
  bool at_line_start = out_.empty() || out_.back() == '\n';
  if (file_ == t.file && t.line >= line_ && t.line - line_ <= max_blank_lines) {
    while (line_ < t.line) newline();
    return;
  }
  if (!at_line_start) newline();
  out_ += "#line " + std::to_string(t.line) + " " + cpp_string_literal(t.file->path) + "\n";
  file_ = t.file;
  line_ = t.line;
}

void writer::separate(std::string_view next, bool space_before) {
  if (out_.empty() || next.empty()) return;
  char last = out_.back();
  if (last == '\n' || last == ' ') return;
  // Characters that would read as one token if written side by side.
  static constexpr std::string_view fusing[] = {"++", "--", "->", "<<", ">>", "<=", ">=", "==",
                                                "!=", "&&", "||", "+=", "-=", "*=", "/=", "%=",
                                                "&=", "|=", "^=", "::", "..", "/*", "//", "<:", "%:"};
  bool glue = word_char(last) && (word_char(next[0]) || next[0] == '"' || next[0] == '\'');
  bool fuse = false;
  for (std::string_view f : fusing) fuse = fuse || (f[0] == last && f[1] == next[0]);
  bool spaced = space_before && last != '(' && last != '[' && next[0] != ')' && next[0] != ']' &&
                next[0] != ',' && next[0] != ';';
  if (glue || fuse || spaced) out_ += ' ';
}

void writer::token(const vvc::token& t) {
  sync(t);
  separate(t.text, t.space_before);
  out_ += t.text;
  // A string continued with a backslash, or a raw string, spans lines: the
  // next token's line is counted from the line this one ends on.
  for (char c : t.text)
    if (c == '\n') ++line_;
}

void writer::text(std::string_view s) {
  separate(s, false);
  out_ += s;
}

void writer::at(const vvc::token& t) {
  sync(t);
  separate("x", t.space_before);
}

void writer::lines(std::string_view s) {
  if (!out_.empty() && out_.back() != '\n') out_ += '\n';
  out_ += s;
  if (!out_.empty() && out_.back() != '\n') out_ += '\n';
  file_ = nullptr;
}

void writer::generated(std::string_view s) {
  std::string text = "#line 1 \"<vvc generated>\"\n";
  text += s;
  lines(text);
}

void writer::preproc(const vvc::token& t) {
  sync(t);
  if (!out_.empty() && out_.back() != '\n') {
    out_ += '\n';
    file_ = nullptr;
    sync(t);
  }
  out_ += t.text;
  for (char c : t.text)
    if (c == '\n') ++line_;
  newline();
}

}  // namespace vvc
