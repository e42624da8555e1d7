// Reading the text formats (OBJ, OFF, ASCII STL) line by line, with the
// line number of everything read, so that every error can say where it is.
// Numbers are read with std::from_chars: exact, and independent of the C
// locale. Internal to vv_formats.
#pragma once

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <vv/error.hpp>

namespace vv::formats {

//! The lines of a text, each split into words, comments (from a '#' to the
//! end of the line, also right after a word: `0.9#red`) left out. A line ending in a backslash goes on with the
//! next one when `continuations` is set (OBJ).
class line_scanner {
 public:
  line_scanner(std::string path, std::string_view text, bool continuations = false)
      : path_(std::move(path)), text_(text), continuations_(continuations) {}

  //! Moves to the next line; false at the end of the text.
  bool next() {
    words_.clear();
    if (at_ >= text_.size()) return false;
    line_ = next_line_;
    bool more = true;
    while (more) {
      std::size_t end = text_.find('\n', at_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(at_, end - at_);
      at_ = end + 1;
      ++next_line_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      more = continuations_ && !line.empty() && line.back() == '\\' && at_ < text_.size();
      if (more) line.remove_suffix(1);
      if (split(line)) more = false;  // a comment ends the statement
    }
    return true;
  }

  //! The words of the current line (none for a blank or comment line).
  const std::vector<std::string_view>& words() const noexcept { return words_; }
  //! The current line's number, from 1.
  int line() const noexcept { return line_; }
  const std::string& path() const noexcept { return path_; }

  //! An error at the current line.
  [[noreturn]] void fail(const std::string& problem) const { throw error(path_, line_, problem); }

 private:
  // Adds the words of one physical line; true when a comment cut it short.
  bool split(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      if (i >= line.size()) break;
      if (line[i] == '#') return true;
      std::size_t start = i;
      while (i < line.size() && !is_blank(line[i]) && line[i] != '#') ++i;
      words_.push_back(line.substr(start, i - start));
    }
    return false;
  }
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

  std::string path_;
  std::string_view text_;
  bool continuations_;
  std::size_t at_ = 0;
  int line_ = 0, next_line_ = 1;
  std::vector<std::string_view> words_;
};

//! A word that is a whole number (an optional sign; no point, no exponent).
enum class integer_result { ok, not_a_number, not_whole, too_large };

inline integer_result read_integer(std::string_view word, std::int64_t& out) {
  const char* begin = word.data();
  const char* end = begin + word.size();
  if (begin != end && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, out);
  if (ec == std::errc::result_out_of_range) return integer_result::too_large;
  if (ec != std::errc() || ptr == begin) return integer_result::not_a_number;
  if (ptr != end) {
    // "2.9" or "3e2": a number, but not a whole one.
    double ignored;
    auto more = std::from_chars(begin, end, ignored);
    return more.ec == std::errc() && more.ptr == end ? integer_result::not_whole : integer_result::not_a_number;
  }
  return integer_result::ok;
}

//! A word that is a number: exact (the shortest text that reads back is
//! read back to the same double), "nan" and "inf" included; false for
//! anything else, and for a number past the range of a double.
inline bool read_number(std::string_view word, double& out) {
  const char* begin = word.data();
  const char* end = begin + word.size();
  if (begin != end && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, out);
  return ec == std::errc() && ptr == end && ptr != begin;
}

//! "1 vertex", "3 vertices".
inline std::string count_text(std::uint64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

//! "'abc'" for messages, cut short when the word is long.
inline std::string quoted(std::string_view word) {
  constexpr std::size_t most = 40;
  if (word.size() <= most) return "'" + std::string(word) + "'";
  return "'" + std::string(word.substr(0, most)) + "...'";
}

}  // namespace vv::formats
