#include "experiment/runs_table.hpp"

#include <map>
#include <stdexcept>

#include <vv/io/files.hpp>

#include "experiment/csv.hpp"
#include "experiment/run_record.hpp"

namespace vvi {

namespace {

std::vector<std::string> leading_columns(const sweep_plan& plan) {
  std::vector<std::string> cols = {"run", "seed"};
  for (const swept_parameter& p : plan.parameters()) cols.push_back(p.name);
  return cols;
}

std::vector<std::string> leading_cells(const sweep_plan& plan, unsigned number) {
  planned_run r = plan.run(number);
  std::vector<std::string> cells = {std::to_string(r.number), std::to_string(r.seed)};
  cells.insert(cells.end(), r.values.begin(), r.values.end());
  return cells;
}

struct run_plots {
  unsigned number;
  std::vector<std::vector<std::string>> rows;  // the header first
};

}  // namespace

std::string runs_csv(const sweep_plan& plan, const std::string& dir, const std::string& plots) {
  std::vector<run_plots> runs;
  std::vector<std::string> series;  // in order of first appearance
  std::map<std::string, std::size_t> column_of;
  for (unsigned n = 1; n <= plan.size(); ++n) {
    std::string folder = dir + "/" + plan.folder(n);
    if (state_of_run(folder) != run_state::finished) continue;
    std::string path = folder + "/" + plots;
    std::string why;
    std::optional<std::string> text = vv::io::read_file(path, &why);
    if (!text) throw std::runtime_error(path + ": cannot read the run's plots: " + why);
    auto rows = csv::read(*text);
    if (!rows || rows->empty() || rows->front().empty() || rows->front()[0] != "step")
      throw std::runtime_error(path + ": not a plots file of the interpreter (its first column is not \"step\")");
    for (std::size_t c = 1; c < rows->front().size(); ++c) {
      const std::string& name = rows->front()[c];
      if (column_of.emplace(name, series.size()).second) series.push_back(name);
    }
    runs.push_back({n, std::move(*rows)});
  }
  std::vector<std::string> header = leading_columns(plan);
  header.push_back("step");
  header.insert(header.end(), series.begin(), series.end());
  std::string out = csv::row(header);
  for (const run_plots& r : runs) {
    std::vector<std::string> lead = leading_cells(plan, r.number);
    const std::vector<std::string>& names = r.rows.front();
    for (std::size_t i = 1; i < r.rows.size(); ++i) {
      std::vector<std::string> cells = lead;
      cells.push_back(r.rows[i].empty() ? "" : r.rows[i][0]);
      std::vector<std::string> values(series.size());
      for (std::size_t c = 1; c < names.size() && c < r.rows[i].size(); ++c) values[column_of[names[c]]] = r.rows[i][c];
      cells.insert(cells.end(), values.begin(), values.end());
      out += csv::row(cells);
    }
  }
  return out;
}

std::string failed_csv(const sweep_plan& plan, const std::string& dir) {
  std::vector<std::string> header = leading_columns(plan);
  header.push_back("line");
  header.push_back("reason");
  std::string out = csv::row(header);
  for (unsigned n = 1; n <= plan.size(); ++n) {
    std::string folder = dir + "/" + plan.folder(n);
    if (state_of_run(folder) != run_state::failed) continue;
    run_failure f = read_failure(folder);
    std::vector<std::string> cells = leading_cells(plan, n);
    cells.push_back(f.line);
    cells.push_back(f.reason);
    out += csv::row(cells);
  }
  return out;
}

}  // namespace vvi
