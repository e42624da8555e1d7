#include "experiment/csv.hpp"

namespace vvi::csv {

std::string cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string row(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cell(cells[i]);
  return out + "\n";
}

std::optional<std::vector<std::vector<std::string>>> read(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> cells;
  std::string current;
  std::size_t i = 0;
  bool row_open = false;
  while (i < text.size()) {
    char c = text[i];
    row_open = true;
    if (c == '"' && current.empty()) {
      // A quoted cell: up to the quote that is not doubled.
      for (++i;; ++i) {
        if (i >= text.size()) return std::nullopt;
        if (text[i] == '"') {
          if (i + 1 < text.size() && text[i + 1] == '"') current += '"', ++i;
          else break;
        } else {
          current += text[i];
        }
      }
      ++i;
      if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') return std::nullopt;
      continue;
    }
    if (c == ',') {
      cells.push_back(current), current.clear();
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      cells.push_back(current), current.clear();
      rows.push_back(cells), cells.clear();
      row_open = false;
    } else {
      current += c;
    }
    ++i;
  }
  if (row_open) {
    cells.push_back(current);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace vvi::csv
