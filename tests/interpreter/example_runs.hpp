// Running the programs of examples/ in batch mode and reading what they
// leave: the tests of the biological examples share these.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace example_runs {

//! examples/NAME.vvp in the source tree.
inline std::string path(const std::string& name) { return VV_SOURCE_DIR "/examples/" + name + ".vvp"; }

//! The examples whose runs here are long: at the suite's -O0 (VV_OPT=0)
//! their tests ran 17 s (daffodil_corona), 12 s (korn_spalding) and 10 s
//! (phyllotaxis) of CPU, at -O1 1.4 to 2.9 s, for 2 to 5 s more compiling.
//! These run as users run them, at the default -O1; the others at $VV_OPT.
inline bool runs_long(const std::string& name) {
  return name == "daffodil_corona" || name == "korn_spalding" || name == "phyllotaxis";
}

//! vvinterpreter --batch --quiet ARGS examples/NAME.vvp.
inline test_run::result batch(const std::string& name, std::vector<std::string> args) {
  std::vector<std::string> all = {"--batch", "--quiet"};
  if (runs_long(name)) all.insert(all.end(), {"--opt", "1"});
  all.insert(all.end(), args.begin(), args.end());
  all.push_back(path(name));
  return test_run::run(test_run::interpreter(all), 300);
}

//! What a failed run printed, for an assertion's message.
inline std::string report(const test_run::result& r) { return "stdout:\n" + r.out + "stderr:\n" + r.err; }

//! Runs NAME for STEPS with its end block and exports the mesh to a scratch
//! file named after TAG, whose path is left in `exported`.
inline test_run::result run_and_export(const std::string& name, const std::string& steps, const std::string& tag,
                                       std::string& exported, std::vector<std::string> extra = {}) {
  exported = test_files::scratch_dir() + tag + ".vvm";
  std::vector<std::string> args = {"--steps", steps, "--end", "--export", exported};
  args.insert(args.end(), extra.begin(), extra.end());
  return batch(name, args);
}

//! Two runs of NAME for STEPS export the same, non-empty bytes.
inline void expect_runs_export_the_same_bytes(const std::string& name, const std::string& steps) {
  std::string first, second;
  test_run::result a = run_and_export(name, steps, name + "_run_a", first);
  test_run::result b = run_and_export(name, steps, name + "_run_b", second);
  ASSERT_EQ(a.status, 0) << report(a);
  ASSERT_EQ(b.status, 0) << report(b);
  const std::string bytes = test_files::slurp(first);
  EXPECT_FALSE(bytes.empty());
  EXPECT_EQ(bytes, test_files::slurp(second));
}

//! One column of a --plots CSV file, by its header; the header must have it.
inline std::vector<std::string> csv_column(const std::string& csv_path, const std::string& column_name) {
  std::istringstream in(test_files::slurp(csv_path));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::istringstream header_cells(line);
  for (std::string cell; std::getline(header_cells, cell, ',');) header.push_back(cell);
  std::size_t column = header.size();
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == column_name) column = i;
  EXPECT_LT(column, header.size()) << "no column '" << column_name << "' in " << line;
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    for (std::size_t i = 0; std::getline(cells, cell, ','); ++i)
      if (i == column) break;
    values.push_back(cell);
  }
  return values;
}

}  // namespace example_runs
