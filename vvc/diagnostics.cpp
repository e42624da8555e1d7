#include "diagnostics.hpp"

#include <algorithm>

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

std::string format(const diagnostic& d) {
  std::string out = (d.file ? d.file->path : std::string("<input>")) + ":" +
                    std::to_string(d.line) + ":" + std::to_string(d.col) + ": error: " + d.message +
                    "\n";
  if (d.file) {
    std::string_view text = d.file->line(d.line);
    out += "  ";
    out += text;
    out += "\n  ";
    // One space (or tab, to line up) per character before the column;
    // columns count characters, so UTF-8 continuation bytes add nothing.
    int col = 1;
    for (std::size_t i = 0; i < text.size() && col < d.col; ++i) {
      unsigned char c = static_cast<unsigned char>(text[i]);
      if ((c & 0xC0) == 0x80) continue;
      out += c == '\t' ? '\t' : ' ';
      ++col;
    }
    out += "^\n";
  }
  return out;
}

void diagnostics::print(std::ostream& os) const {
  for (const auto& d : list_) os << format(d);
  if (saturated()) os << "too many errors; stopping\n";
}

}  // namespace vvc
