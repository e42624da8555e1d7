// The series a model records with proxy.plot, as a table: one row per step
// that recorded anything, one column per series (batch --plots FILE.csv,
// the viewer's plots panel).
#pragma once

#include <string>
#include <vector>

#include <model/abi.hpp>

namespace vvi {

//! CSV (RFC 4180): the header "step,NAME,...", then one row per step in
//! increasing order; a series without a value at a step has an empty cell.
//! Numbers are written so they read back exactly.
std::string plots_csv(const std::vector<vv_plot_series>& plots);

//! Writes plots_csv to a file, atomically: "" or why not.
std::string write_plots(const std::string& path, const std::vector<vv_plot_series>& plots);

}  // namespace vvi
