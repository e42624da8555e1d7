// CSV as RFC 4180 has it, the dialect of the host's plots files
// (runner/plots.hpp): the experiments read each run's plots and write the
// sweep's tables in it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace vvi::csv {

//! A cell: quoted when it holds a comma, a quote or a line break (quotes
//! doubled), else as it is.
std::string cell(const std::string& text);
//! Cells joined by commas, ended by "\n".
std::string row(const std::vector<std::string>& cells);

//! The rows of a CSV text, cells unquoted; std::nullopt for a quote that
//! never closes or text after a closing quote.
std::optional<std::vector<std::vector<std::string>>> read(const std::string& text);

}  // namespace vvi::csv
