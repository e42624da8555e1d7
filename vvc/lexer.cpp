#include "lexer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include <vv/io/files.hpp>

namespace vvc {

namespace {

// Longest first, so that the first match is the longest.
constexpr std::array<std::string_view, 44> punctuators = {
    "<=>", "<<=", ">>=", "->*", "...", "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=",
    "&&",  "||",  "+=",  "-=",  "*=",  "/=", "%=", "&=", "|=", "^=", "##", ".*", "{",  "}",  "[",
    "]",   "(",   ")",   ";",   ":",   ",",  ".",  "+",  "-",  "*",  "/",  "%",  "<",  ">"};
constexpr std::string_view single_punct = "&|^~!=?#";

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// U+2018 LEFT SINGLE QUOTATION MARK, the typographic backtick.
constexpr std::string_view left_quote = "\xE2\x80\x98";

// What the lexers of a file and the files it includes share.
struct include_state {
  std::vector<const source_file*> stack;  // files being read, outermost first
  std::vector<std::string> once;          // files that said #pragma once
};

class lexer {
 public:
  lexer(const source_file& f, source_set& sources, diagnostics& diag, include_state& state,
        std::vector<token>& out)
      : f_(f), s_(f.text), sources_(sources), diag_(diag), state_(state), out_(out) {}

  void run() {
    bool space = false;
    bool line_start = true;
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (c == '\n') {
        ++pos_, ++line_, line_begin_ = pos_;
        space = true, line_start = true;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {  // line ends are LF (source_file)
        ++pos_, space = true;
        continue;
      }
      if (c == '\\' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '\n') {
        ++pos_, space = true;  // a line continuation between tokens
        continue;
      }
      if (starts("//")) {
        line_comment();
        space = true;
        continue;
      }
      if (starts("/*")) {
        block_comment();
        space = true;
        continue;
      }
      token t;
      t.file = &f_;
      t.line = line_;
      t.col = column(pos_);
      t.space_before = space;
      t.line_start = line_start;
      std::size_t begin = pos_;
      if (c == '#' && line_start) {
        preprocessor(t, begin);
      } else if (!scan(t)) {
        continue;  // an error was reported and the text skipped
      }
      if (t.kind != tok::preproc || t.text.size() > 0) {
        if (t.text.empty()) t.text = std::string_view(s_).substr(begin, pos_ - begin);
        if (t.kind != tok::eof) out_.push_back(t);
      }
      space = false;
      line_start = false;
    }
  }

 private:
  bool starts(std::string_view p) const { return std::string_view(s_).substr(pos_, p.size()) == p; }

  void error_here(std::size_t at, int line, const std::string& msg) {
    diag_.error(&f_, line, line == line_ ? column(at) : column_in(line, at), msg);
  }

  // Columns count characters, not bytes (as compilers report them): UTF-8
  // continuation bytes do not start a column. Counted from the last place
  // asked on the same line, so long lines stay linear.
  int column(std::size_t at) {
    if (col_line_ != line_ || at < col_pos_) {
      col_line_ = line_;
      col_pos_ = line_begin_;
      col_ = 1;
    }
    for (; col_pos_ < at; ++col_pos_)
      if ((static_cast<unsigned char>(s_[col_pos_]) & 0xC0) != 0x80) ++col_;
    return col_;
  }
  int column_in(int line, std::size_t at) const {
    std::size_t begin = f_.line_starts[static_cast<std::size_t>(line - 1)];
    int col = 1;
    for (std::size_t i = begin; i < at; ++i)
      if ((static_cast<unsigned char>(s_[i]) & 0xC0) != 0x80) ++col;
    return col;
  }

  void block_comment() {
    std::size_t at = pos_;
    int line = line_;
    pos_ += 2;
    while (pos_ < s_.size() && !starts("*/")) {
      if (s_[pos_] == '\n') ++line_, line_begin_ = pos_ + 1;
      ++pos_;
    }
    if (pos_ >= s_.size()) {
      error_here(at, line, "unterminated comment: '/*' has no '*/'");
      return;
    }
    pos_ += 2;
  }

  // A // comment runs to the end of the line, and on over each line that a
  // backslash at its end continues: C++ splices lines before it removes
  // comments.
  void line_comment() {
    for (;;) {
      while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      if (pos_ >= s_.size() || pos_ == 0 || s_[pos_ - 1] != '\\') return;
      ++pos_, ++line_, line_begin_ = pos_;  // the next line is comment too
    }
  }

  // A preprocessor line, with its continuations. `#include "x.vvp"` brings
  // in the tokens of x.vvp instead.
  void preprocessor(token& t, std::size_t begin) {
    while (pos_ < s_.size() && s_[pos_] != '\n') {
      if (s_[pos_] == '\\' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '\n')
        ++pos_, ++line_, line_begin_ = pos_ + 1;
      else if (starts("/*")) {
        block_comment();
        continue;
      }
      ++pos_;
    }
    t.kind = tok::preproc;
    t.text = std::string_view(s_).substr(begin, pos_ - begin);
    std::string included;
    if (vvp_include(t.text, included)) {
      include(t, included);
      t.text = std::string_view();  // nothing of the directive itself remains
    } else if (std::string header; header_include(t.text, header)) {
      check_header(t, header);
    } else if (is_pragma_once(t.text)) {
      // Included .vvp files are pasted into one translation unit, where the
      // pragma would mean nothing: the lexer keeps the promise instead.
      state_.once.push_back(same_file(f_.path));
      t.text = std::string_view();
    }
  }

  static bool is_pragma_once(std::string_view line) {
    std::string words;
    for (char c : line.substr(1))
      if (c != ' ' && c != '\t') words += c;
    return words == "pragmaonce";
  }

  static bool vvp_include(std::string_view line, std::string& path) {
    std::size_t i = 1;
    auto skip = [&] {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    };
    skip();
    if (line.substr(i, 7) != "include") return false;
    i += 7;
    skip();
    if (i >= line.size() || line[i] != '"') return false;
    std::size_t close = line.find('"', i + 1);
    if (close == std::string_view::npos) return false;
    path = std::string(line.substr(i + 1, close - i - 1));
    return path.size() > 4 && path.compare(path.size() - 4, 4, ".vvp") == 0;
  }

  // `#include "x.h"` or `#include <x.h>` (not a .vvp: those are read here).
  static bool header_include(std::string_view line, std::string& path) {
    std::size_t i = 1;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (line.substr(i, 7) != "include") return false;
    i += 7;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size() || (line[i] != '"' && line[i] != '<')) return false;
    std::size_t close = line.find(line[i] == '"' ? '"' : '>', i + 1);
    if (close == std::string_view::npos) return false;
    path = std::string(line.substr(i, close - i + 1));  // with its quotes or brackets
    return true;
  }

  // A header the compiler would read that is no regular file, or is too
  // large, is refused here: g++ would read `#include "/dev/zero"` without
  // end. Relative quoted names are looked for beside the including file;
  // what is not found there is left to the compiler's own search.
  void check_header(const token& at, const std::string& spelled) {
    std::string name = spelled.substr(1, spelled.size() - 2);
    bool quoted = spelled[0] == '"';
    if (name.empty() || (name[0] != '/' && !quoted)) return;
    std::string path = vv::io::resolve(f_.folder(), name);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return;
    if (std::optional<std::string> why = vv::io::unreadable_file(path, vv::io::program_file_limit))
      diag_.error(at, "cannot include " + spelled + ": " + *why);
  }

  // The one name of a file, however a path spells it ("./a.vvp", "x/../a.vvp",
  // a link): include cycles and #pragma once compare these.
  static std::string same_file(const std::string& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
  }

  void include(const token& at, const std::string& name) {
    std::string path = vv::io::resolve(f_.folder(), name);
    std::string file = same_file(path);
    for (const std::string& done : state_.once)
      if (done == file) return;
    for (const source_file* open : state_.stack)
      if (same_file(open->path) == file) {
        diag_.error(at, "'" + name + "' includes itself (through #include)");
        return;
      }
    std::string why;
    const source_file* inc = sources_.load(path, &why);
    if (!inc) {
      diag_.error(at, "cannot open included file '" + name + "': " + why);
      return;
    }
    state_.stack.push_back(inc);
    lexer(*inc, sources_, diag_, state_, out_).run();
    state_.stack.pop_back();
  }

  bool scan(token& t) {
    char c = s_[pos_];
    if (ident_start(c)) return word(t);
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && pos_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_ + 1]))))
      return number(t);
    if (c == '"') return quoted(t, '"', tok::string);
    if (c == '\'') return quoted(t, '\'', tok::character);
    if (c == '`') return ++pos_, t.kind = tok::backtick, true;
    if (starts(left_quote)) return pos_ += left_quote.size(), t.kind = tok::backtick, true;
    if (c == '$') return ++pos_, t.kind = tok::dollar, true;
    if (c == '@') return ++pos_, t.kind = tok::at, true;
    for (std::string_view p : punctuators)  // the first character first: a long line of them stays quick
      if (p[0] == c && starts(p)) return pos_ += p.size(), t.kind = tok::punct, true;
    if (single_punct.find(c) != std::string_view::npos) return ++pos_, t.kind = tok::punct, true;
    std::size_t at = pos_;
    error_here(at, line_, "stray " + describe_stray() + " in program");
    return false;
  }

  // Names the character at pos_ and steps over it: 'x', '×' (U+00D7), or
  // "byte 0xC3" when it is not valid UTF-8.
  std::string describe_stray() {
    unsigned char c = static_cast<unsigned char>(s_[pos_]);
    if (c < 0x80) {
      ++pos_;
      if (std::isprint(c)) return std::string("'") + static_cast<char>(c) + "'";
      return "byte " + std::to_string(c);
    }
    int n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
    unsigned long cp = n == 4 ? (c & 0x07u) : n == 3 ? (c & 0x0Fu) : (c & 0x1Fu);
    bool valid = n > 0 && pos_ + static_cast<std::size_t>(n) <= s_.size();
    for (int i = 1; valid && i < n; ++i) {
      unsigned char d = static_cast<unsigned char>(s_[pos_ + static_cast<std::size_t>(i)]);
      valid = (d & 0xC0) == 0x80;
      cp = (cp << 6) | (d & 0x3Fu);
    }
    if (!valid) {
      ++pos_;
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", c);
      return std::string("byte ") + hex;
    }
    std::string shown = s_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    char code[16];
    std::snprintf(code, sizeof code, "U+%04lX", cp);
    return "'" + shown + "' (" + code + ")";
  }

  bool word(token& t) {
    std::size_t begin = pos_;
    while (pos_ < s_.size() && ident_char(s_[pos_])) ++pos_;
    std::string_view w = std::string_view(s_).substr(begin, pos_ - begin);
    if (pos_ < s_.size() && s_[pos_] == '"' && (w == "R" || w == "u8R" || w == "uR" || w == "UR" || w == "LR"))
      return raw_string(t, begin);
    if (pos_ < s_.size() && (s_[pos_] == '"' || s_[pos_] == '\'') &&
        (w == "u8" || w == "u" || w == "U" || w == "L")) {
      char q = s_[pos_];
      bool ok = quoted(t, q, q == '"' ? tok::string : tok::character);
      t.text = std::string_view(s_).substr(begin, pos_ - begin);
      return ok;
    }
    t.kind = tok::identifier;
    return true;
  }

  // A pp-number, as C++ defines it: a sign belongs to it after e, E, p, P
  // (so 1e+5 is one token), and ' separates digits.
  bool number(token& t) {
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if ((c == '+' || c == '-') && std::strchr("eEpP", s_[pos_ - 1]))
        ++pos_;
      else if (ident_char(c) || c == '.')
        ++pos_;
      else if (c == '\'' && pos_ + 1 < s_.size() && ident_char(s_[pos_ + 1]))
        pos_ += 2;
      else
        break;
    }
    t.kind = tok::number;
    return true;
  }

  bool quoted(token& t, char q, tok kind) {
    ++pos_;
    while (pos_ < s_.size() && s_[pos_] != q && s_[pos_] != '\n') {
      if (s_[pos_] == '\\' && pos_ + 1 < s_.size()) {
        if (s_[pos_ + 1] == '\n') ++line_, line_begin_ = pos_ + 2;
        ++pos_;
      }
      ++pos_;
    }
    if (pos_ >= s_.size() || s_[pos_] != q) {
      diag_.error(&f_, t.line, t.col,
                  q == '"' ? "unterminated string literal" : "unterminated character literal");
      return false;
    }
    ++pos_;
    while (pos_ < s_.size() && ident_char(s_[pos_])) ++pos_;  // user-defined suffix
    t.kind = kind;
    return true;
  }

  bool raw_string(token& t, std::size_t begin) {
    ++pos_;  // the quote
    std::size_t open = s_.find('(', pos_);
    if (open == std::string::npos || open - pos_ > 16) {
      diag_.error(&f_, t.line, t.col, "malformed raw string literal");
      pos_ = s_.size();
      return false;
    }
    std::string close = ")" + s_.substr(pos_, open - pos_) + "\"";
    std::size_t end = s_.find(close, open);
    if (end == std::string::npos) {
      diag_.error(&f_, t.line, t.col, "unterminated raw string literal");
      pos_ = s_.size();
      return false;
    }
    for (std::size_t i = pos_; i < end; ++i)
      if (s_[i] == '\n') ++line_, line_begin_ = i + 1;
    pos_ = end + close.size();
    while (pos_ < s_.size() && ident_char(s_[pos_])) ++pos_;
    t.kind = tok::string;
    t.text = std::string_view(s_).substr(begin, pos_ - begin);
    return true;
  }

  const source_file& f_;
  const std::string& s_;
  source_set& sources_;
  diagnostics& diag_;
  include_state& state_;
  std::vector<token>& out_;
  std::size_t pos_ = 0;
  std::size_t line_begin_ = 0;
  int line_ = 1;
  int col_line_ = 0;  // column() memo: line, byte position, column
  std::size_t col_pos_ = 0;
  int col_ = 1;
};

}  // namespace

std::vector<token> lex(const source_file& file, source_set& sources, diagnostics& diag) {
  std::vector<token> out;
  include_state state;
  state.stack.push_back(&file);
  lexer(file, sources, diag, state, out).run();
  token eof;
  eof.kind = tok::eof;
  eof.file = &file;
  eof.line = static_cast<int>(file.line_starts.size());
  eof.col = static_cast<int>(file.line(eof.line).size()) + 1;
  eof.line_start = true;
  out.push_back(eof);
  return out;
}

}  // namespace vvc
