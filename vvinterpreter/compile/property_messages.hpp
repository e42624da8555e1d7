// The compiler's "has no member named" about a vertex, a half-edge record or
// a mesh, told in the program's words. A misspelt `v$position` makes g++
// name the types vvc generates ("'const vv::traits<vv_vertex_props, ...>::
// vertex_props' has no member named 'position'", clang "no member named
// 'position' in 'vv_vertex_props'"); the modeller wrote a vertex block, so
// the message names the vertex and lists its properties.
#pragma once

#include <string>
#include <vector>

namespace vvi {

//! The fields the program's property blocks declare (vvc knows them).
struct property_fields {
  std::vector<std::string> edge, vertex, mesh;
};

//! `message` (what follows "file:line:col: ": g++'s "error: '...' has no
//! member named 'x'" or clang's "error: no member named 'x' in '...'")
//! rewritten for a member missing from a property block; "" when it is
//! about anything else.
std::string property_message(const std::string& message, const property_fields& fields);

}  // namespace vvi
