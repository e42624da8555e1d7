#include "runner/plots.hpp"

#include <map>
#include <vector>

#include <vv/fields.hpp>
#include <vv/io/files.hpp>

#include "runner/output_file.hpp"

namespace vvi {

namespace {

// A name with a comma, a quote or a line break is quoted, quotes doubled.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string plots_csv(const std::vector<vv_plot_series>& plots) {
  std::string out = "step";
  for (const vv_plot_series& s : plots) out += "," + csv_cell(s.name);
  out += "\n";
  // step → the cell of each series (empty where it recorded nothing).
  std::map<unsigned, std::vector<std::string>> rows;
  for (std::size_t column = 0; column < plots.size(); ++column) {
    const vv_plot_series& s = plots[column];
    for (std::size_t i = 0; i < s.count; ++i) {
      std::vector<std::string>& row = rows[s.steps[i]];
      row.resize(plots.size());
      row[column] = vv::value_to_text(s.values[i]);
    }
  }
  for (auto& [step, cells] : rows) {
    cells.resize(plots.size());
    out += std::to_string(step);
    for (const std::string& c : cells) out += "," + c;
    out += "\n";
  }
  return out;
}

std::string write_plots(const std::string& path, const std::vector<vv_plot_series>& plots) {
  return write_output(path, [&](const std::string& to) -> std::string {
    try {
      vv::io::write_text_file(to, plots_csv(plots));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  });
}

}  // namespace vvi
