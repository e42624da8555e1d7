// The emitter: C++ from the syntax tree.
//
// Output layout (see docs/translator.md):
//   1. vvlib includes; `vertex` and `mesh` declared on a forward-declared
//      traits struct (so property structs may hold vertices);
//   2. the program in source order, with property blocks as structs
//      (fields value-initialised, a vv_fields visitor for .vvm files) and
//      execution blocks as static functions;
//   3. right after the last property block (or at the top): the traits,
//      the model's context, `proxy`, and the vertex-creation helpers;
//   4. at the end: the plugin's extern "C" entry points and the table of
//      global meshes.
// Every source token is written on its .vvp line (#line), so compiler
// errors and run-time errors (vv::where) name the .vvp file and line.
#pragma once

#include <string>

#include "syntax.hpp"

namespace vvc {

struct emit_options {
  std::string version;     // written into the header comment
  std::string source_dir;  // the main .vvp's folder: relative paths resolve against it
};

std::string emit(const program& p, const emit_options& options);

}  // namespace vvc
