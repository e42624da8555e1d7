// The program's global variables, for checkpoints (vv_plugin::globals):
// every variable a top-level declaration (or a namespace in it) defines,
// the parameters, and the `static` variables inside functions, which a
// checkpoint cannot reach and must name. The C++ compiler decides the rest
// (constness, the type's saveability) from decltype of each name, so this
// only needs to find names, their lines and how their types are written.
#pragma once

#include <string>
#include <vector>

#include "syntax.hpp"

namespace vvc {

struct global_variable {
  std::string name;   // qualified by its namespaces (N::x)
  std::string type;   // as the declaration writes it ("std::vector<vertex>", "int*")
  int line = 0;
  bool in_function = false;  // a `static` inside a function body
};

//! In source order.
std::vector<global_variable> find_globals(const program& p);

}  // namespace vvc
