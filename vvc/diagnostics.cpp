#include "diagnostics.hpp"

namespace vvc {

void diagnostics::error(const token& at, std::string message) {
  error(at.file, at.line, at.col, std::move(message));
}

void diagnostics::error(const source_file* file, int line, int col, std::string message) {
  if (saturated()) return;
  // The same place twice means recovery went round once more: keep one.
  for (const auto& d : list_)
    if (d.file == file && d.line == line && d.col == col) return;
  list_.push_back({file, line, col, std::move(message)});
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
    // Keep tabs so the caret lines up under the same column.
    for (int i = 1; i < d.col && static_cast<std::size_t>(i - 1) < text.size(); ++i)
      out += text[static_cast<std::size_t>(i - 1)] == '\t' ? '\t' : ' ';
    out += "^\n";
  }
  return out;
}

void diagnostics::print(std::ostream& os) const {
  for (const auto& d : list_) os << format(d);
  if (saturated()) os << "too many errors; stopping\n";
}

}  // namespace vvc
