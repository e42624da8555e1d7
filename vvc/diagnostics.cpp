#include "diagnostics.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

namespace vvc {

void diagnostics::error(const token& at, std::string message) {
  error(at.file, at.line, at.col, std::move(message));
}

void diagnostics::error(const source_file* file, int line, int col, std::string message) {
  if (!held_from_.empty()) {
    ++held_;
    return;
  }
  if (saturated()) return;
  // The same place twice means recovery went round once more: keep one.
  for (const auto& d : list_)
    if (d.file == file && d.line == line && d.col == col) return;
  std::size_t rank = file_rank(file);
  auto later = std::find_if(list_.begin(), list_.end(), [&](const diagnostic& d) {
    std::size_t r = file_rank(d.file);
    return r > rank || (r == rank && (d.line > line || (d.line == line && d.col > col)));
  });
  list_.insert(later, {file, line, col, std::move(message)});
}

std::size_t diagnostics::file_rank(const source_file* f) {
  auto it = std::find(files_.begin(), files_.end(), f);
  if (it != files_.end()) return static_cast<std::size_t>(it - files_.begin());
  files_.push_back(f);
  return files_.size() - 1;
}

namespace {

bool starts_character(char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }

// The byte offset of each character of text (columns count characters, so
// UTF-8 continuation bytes start none), and text.size() at the end.
std::vector<std::size_t> character_offsets(std::string_view text) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (starts_character(text[i])) at.push_back(i);
  at.push_back(text.size());
  return at;
}

}  // namespace

std::string format(const diagnostic& d) {
  std::string out = (d.file ? d.file->path : std::string("<input>")) + ":" +
                    std::to_string(d.line) + ":" + std::to_string(d.col) + ": error: " + d.message +
                    "\n";
  if (!d.file) return out;
  std::string_view text = d.file->line(d.line);
  // A long line (a generated table, a minified expression) is cut to the
  // columns around the caret, with "..." where it is cut.
  std::vector<std::size_t> at = character_offsets(text);
  const std::size_t characters = at.size() - 1;
  const std::size_t caret = std::min(static_cast<std::size_t>(std::max(d.col, 1) - 1), characters);
  std::size_t first = 0, last = characters;  // the characters shown: [first, last)
  if (characters > max_shown_columns) {
    first = caret > max_shown_columns / 2 ? caret - max_shown_columns / 2 : 0;
    last = std::min(characters, first + max_shown_columns);
    first = last - max_shown_columns;
  }
  const std::string_view cut = "...";
  out += "  ";
  if (first > 0) out += cut;
  out += text.substr(at[first], at[last] - at[first]);
  if (last < characters) out += cut;
  out += "\n  ";
  if (first > 0) out.append(cut.size(), ' ');
  // One space (or tab, to line up) per character before the caret.
  for (std::size_t i = first; i < caret; ++i) out += text[at[i]] == '\t' ? '\t' : ' ';
  out += "^\n";
  return out;
}

void diagnostics::print(std::ostream& os) const {
  for (const auto& d : list_) os << format(d);
  if (saturated()) os << "too many errors; stopping\n";
}

}  // namespace vvc
