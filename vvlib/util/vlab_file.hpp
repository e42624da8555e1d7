// Reading and writing VLAB's data files: the whole file at once, a cursor
// over its numbered lines, and numbers read and written independently of
// the C locale. Every problem becomes a vv::error "file:line: problem"
// (line 0, "file: problem", for the file as a whole).
#pragma once

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <vv/error.hpp>
#include <vv/io/files.hpp>

namespace util::vlab {

//! The whole file (the file objects resolve relative names first:
//! vv/file_objects.hpp). A path that is no regular file (a folder, a FIFO,
//! a link to a device), or a file over vv::io::data_file_limit, is refused
//! unread.
inline std::string read_bytes(const std::string& path) {
  std::string why;
  std::optional<std::string> bytes = vv::io::read_file(path, &why, vv::io::data_file_limit);
  if (!bytes) throw vv::error(path, 0, "cannot open: " + why);
  return std::move(*bytes);
}

//! Writes by way of a temporary file renamed over the target, so that a
//! host watching the file never rereads it half written.
inline void write_bytes(const std::string& path, const std::string& bytes) {
  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw vv::error(path, 0, std::string("cannot write: ") + std::strerror(errno));
    out << bytes;
    out.close();
    if (!out) {
      std::remove(temporary.c_str());
      throw vv::error(path, 0, "cannot write: the write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw vv::error(path, 0, "cannot write: " + ec.message());
  }
}

inline std::string_view trim(std::string_view s) {
  auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

inline std::vector<std::string_view> words(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

//! Text quoted for a message, shortened so one bad line stays one line.
inline std::string quoted(std::string_view text) {
  constexpr std::size_t longest = 40;
  if (text.size() > longest) return "'" + std::string(text.substr(0, longest)) + "...'";
  return "'" + std::string(text) + "'";
}

//! A finite decimal number, the whole word ("0.5", "-1e-3", "+2").
inline bool parse_number(std::string_view word, double& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  if (word.empty()) return false;
  auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  return ec == std::errc() && end == word.data() + word.size() && std::isfinite(value);
}

//! A whole number >= 0 written with digits only.
inline bool parse_count(std::string_view word, unsigned long& value) {
  if (word.empty() || word.front() == '-' || word.front() == '+') return false;
  auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  return ec == std::errc() && end == word.data() + word.size();
}

//! The shortest text that reads back as exactly the same double.
inline std::string format_number(double value) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;  // 32 characters hold any double
  return std::string(buffer, end);
}

struct text_line {
  int number = 0;         //!< 1-based line in the file
  std::string_view text;  //!< without the line break
};

//! The lines of a text file, read one statement at a time. Blank lines
//! are skipped: VLAB's own readers (fscanf) skip them too.
class text_lines {
 public:
  explicit text_lines(std::string path) : path_(std::move(path)), text_(read_bytes(path_)) {
    std::string_view rest(text_);
    int number = 0;
    while (!rest.empty()) {
      std::size_t end = rest.find('\n');
      std::string_view line = rest.substr(0, end);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // files saved on Windows
      lines_.push_back({++number, line});
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
  }

  // The lines are views into text_, which must not move.
  text_lines(const text_lines&) = delete;
  text_lines& operator=(const text_lines&) = delete;

  const std::string& path() const { return path_; }

  //! True when only blank lines are left.
  bool done() {
    while (next_ < lines_.size() && trim(lines_[next_].text).empty()) ++next_;
    return next_ == lines_.size();
  }

  //! The next non-blank line; at the end of the file, an error saying what
  //! was expected (`expected` is a phrase such as "'samples: N'").
  text_line next(std::string_view expected) {
    if (done()) fail(last_line(), "the file ends where " + std::string(expected) + " was expected");
    return lines_[next_++];
  }

  //! True when the next non-blank line starts with `key`.
  bool next_starts_with(std::string_view key) {
    return !done() && trim(lines_[next_].text).substr(0, key.size()) == key;
  }

  //! The next line as the statement `key value`; the line's text becomes
  //! the value (trimmed). `form` shows the expected statement in the error.
  text_line statement(std::string_view key, std::string_view form) {
    text_line line = next(form);
    std::string_view text = trim(line.text);
    if (text.substr(0, key.size()) != key)
      fail(line.number, "expected " + std::string(form) + ", found " + quoted(text));
    line.text = trim(text.substr(key.size()));
    return line;
  }

  //! The number of the last line in the file (0 for an empty file).
  int last_line() const { return lines_.empty() ? 0 : lines_.back().number; }

  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw vv::error(path_, line, problem);
  }

 private:
  std::string path_;
  std::string text_;
  std::vector<text_line> lines_;
  std::size_t next_ = 0;
};

//! The file's name without folder and extension, for formats without a name.
inline std::string file_stem(const std::string& path) {
  std::string name = std::filesystem::path(path).stem().string();
  return name.empty() ? "noname" : name;
}

//! The statement's value as a whole number.
inline unsigned read_count(const text_lines& lines, const text_line& statement, const char* key) {
  unsigned long count = 0;
  std::vector<std::string_view> w = words(statement.text);
  if (w.size() != 1 || !parse_count(w[0], count) || count > 1000000000ul)
    lines.fail(statement.number, std::string(key) + " expects a whole number, found " + quoted(statement.text));
  return static_cast<unsigned>(count);
}

//! `word` as a number; `what` names it in the error.
inline double read_number(const text_lines& lines, int line, std::string_view word, const char* what) {
  double value = 0;
  if (!parse_number(word, value)) lines.fail(line, std::string(what) + " " + quoted(word) + " is not a number");
  return value;
}

}  // namespace util::vlab
