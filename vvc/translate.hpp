// Translation of one .vvp file (and the .vvp files it includes) to C++.
#pragma once

#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "source.hpp"

namespace vvc {

struct translation {
  bool ok = false;
  std::string cpp;          // the C++ (empty unless ok)
  std::string declarations; // the part of it that depends only on its declarations (emit_declarations)
  std::string header, program;  // cpp in two: the declarations' header and the rest (emit_apart)
  source_set sources;       // the files the diagnostics point into
  diagnostics diag;
  //! The fields each property block declares, in order (empty without the
  //! block): the host names them when the compiler finds no such member.
  struct declared_fields {
    std::vector<std::string> edge, vertex, mesh;
  } fields;
};

//! Translates a file. A file that cannot be read is an error of its own
//! (diag is empty, cpp holds nothing, and `unreadable` says why).
translation translate_file(const std::string& path, std::string* unreadable);
//! Translates text that stands for the file `name`.
translation translate_text(const std::string& name, std::string text);

//! The translator's version.
const char* version();

}  // namespace vvc
