// The quick builds' precompiled header of a model's declarations (vvc's
// emit_apart): the program's text up to its traits, and a call of the
// algebra's common operations (model/common_operations.hpp), precompiled
// by clang on the quick builds' vvlib header, with its templates
// instantiated there and their code compiled once into an object beside it
// (-fpch-codegen). A quick build after an edit then compiles only the
// program's own code: about a third of the time.
//
// An entry (decl-headers/KEY.ID, published as plugins are, model_cache.hpp)
// holds the header, its .pch and object, what the compiler said of it (the
// declarations' warnings, given with every build that uses it), the
// model's own files it read, and a verdict: "usable", or why not (a header
// that does not compile, as when the declarations name the model object:
// quick builds then compile the whole text, as before).
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct declarations_header_request {
  std::string cache_dir;          // holds decl-headers/
  std::string key;                // a hash of its text, the vvlib header it extends and the flags
  std::string text;               // vvc's header
  std::string include;            // vvlib's headers (not listed as dependencies)
  std::vector<std::string> argv;  // the compiler, -include-pch of the vvlib header, the program's flags
  int niceness = 0;               // made ahead of the edits, it gives way to the build
};

struct declarations_header {
  enum state_t { missing, usable, unusable } state = missing;
  std::string pch;       // usable: to compile the program with (-include-pch)
  std::string object;    // usable: its code, to link
  std::string warnings;  // usable: what the compiler said of the declarations
  std::string why;       // unusable: why; missing: why it is not there
  std::string damage;    // built again: what was wrong with the cached one
};

//! The cached header of this key, checked against its manifest and the
//! files it read: missing when there is none or it is out of date.
declarations_header find_declarations_header(const std::string& cache_dir, const std::string& key);

//! The header of this key, built when the cache has none. One that does not
//! compile is stored as unusable, so that later edits do not try again.
declarations_header build_declarations_header(const declarations_header_request& request);

//! Removes the header in `pch`'s entry (the compiler could not read it).
void discard_declarations_header(const std::string& pch);

}  // namespace vvi
