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
//      global meshes. The functions among them that depend only on the
//      declarations (vv_decl_*) are defined here unless VV_DECLARATIONS_APART
//      says that emit_declarations' part is linked in.
// Every source token is written on its .vvp line (#line), so compiler
// errors and run-time errors (vv::where) name the .vvp file and line.
#pragma once

#include <string>

#include "syntax.hpp"

namespace vvc {

struct emit_options {
  std::string version;     // written into the header comment
  std::string source_dir;  // the main .vvp's folder: relative paths resolve against it
  std::string program_name;  // the main .vvp's file name (vv_plugin::program_name)
  std::string program_hash;  // of the text of every .vvp read (vv_plugin::program_hash)
};

std::string emit(const program& p, const emit_options& options);

//! The model's text in two, for quick builds (vvinterpreter's
//! compile/declarations_header.hpp): `header`, emit()'s text up to the
//! traits and their extern templates, without the model object and with
//! each parameter declared extern, then a call of the common operations
//! (model/common_operations.hpp) for clang to instantiate there;
//! `program`, the model object, the parameters' definitions and any
//! execution block, action or pick block among the declarations, then the
//! rest of emit()'s text. Compiled with the header precompiled, the program
//! is the model emit() gives: the header defines no variable of its own.
struct program_apart {
  std::string header, program;
};
program_apart emit_apart(const program& p, const emit_options& options);

//! The part of the model that depends only on its declarations (everything
//! up to the last property block, and the traits): vvlib's file reading
//! and writing and the plugin's mesh functions for the model's traits, the
//! bulk of a model's compile time. Compiled apart and linked with the
//! program compiled with -DVV_DECLARATIONS_APART, it stands for what the
//! program would otherwise compile itself; vvinterpreter caches it by its
//! text, so an edit below the last property block compiles only the
//! program. A definition of the program's that it still holds (a variable,
//! say) shows in the compiled object, which vvinterpreter checks.
std::string emit_declarations(const program& p, const emit_options& options);

}  // namespace vvc
