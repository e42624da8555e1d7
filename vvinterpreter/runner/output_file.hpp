// A file the interpreter writes for the user (--export, --screenshot,
// --plots, the viewer's export): written as vvlib writes every file
// (vv/io/output_file.hpp: a unique temporary renamed into place, links
// followed, devices and FIFOs written through), with the temporary made
// here so that the supervisor knows it: if the model's process dies while
// writing, the temporary goes and the message names the file
// (runner/fault_guard.hpp: note_writing).
#pragma once

#include <functional>
#include <string>

namespace vvi {

//! Writes `path` by write(temporary), which writes the whole file there
//! (its extension is the path's) and returns "" or its error; then puts it
//! in place. Returns "" or the error, about `path`.
std::string write_output(const std::string& path, const std::function<std::string(const std::string&)>& write);

}  // namespace vvi
