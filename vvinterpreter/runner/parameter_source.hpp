// "Save to file" for parameters: the values a user set are written back
// into the `param` lines of the .vvp, so the next build starts from them.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct parameter_value_at {
  std::string name, text;
  int line = 0;  //!< the line of its `param` declaration
};

//! The source with each parameter's value (the text between `=` and `in [`
//! or `;` on its line) replaced by `text`; "" or why not (no such
//! declaration on that line, which is bad_line).
std::string with_parameter_values(std::string& source, const std::vector<parameter_value_at>& values,
                                  int& bad_line);

//! Rewrites the file (atomically) with with_parameter_values: "" or why
//! not, naming the file and line; the file is untouched then.
std::string save_parameter_values(const std::string& path, const std::vector<parameter_value_at>& values);

}  // namespace vvi
