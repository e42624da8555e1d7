// The part of a model that depends only on its declarations (vvc's
// emit_declarations: vvlib's file functions and the plugin's mesh
// functions instantiated for the model's traits, two thirds of a model's
// compile time), compiled once per text into the cache's decls/ folder and
// linked into every build that shares it: an edit below the last property
// block compiles only the program.
//
// An entry (decls/KEY.ID, published as the plugins' are, model_cache.hpp)
// holds the object, its dependency list and the verdict on it: "usable",
// or why not. Its object must define nothing that the program defines too
// and hold no state of its own (object_symbols.hpp): a model that keeps
// variables among its declarations is compiled whole.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct declarations_request {
  std::string cache_dir;          // holds decls/
  std::string key;                // a hash of its text and of everything else that goes into the object
  std::string cpp;                // its text
  std::string include;            // vvlib's headers (in the key; not listed as dependencies)
  std::vector<std::string> argv;  // the compiler and its options, to which "-c -o OBJECT SOURCE" is added
};

struct declarations_part {
  enum state_t { missing, usable, unusable } state = missing;
  std::string object;  // usable: the object to link
  std::string why;     // unusable: why; or a damaged entry that was removed
};

//! The cached part of this key, checked against its manifest and its
//! dependencies: missing when there is none or it is out of date.
declarations_part find_declarations(const std::string& cache_dir, const std::string& key);

//! Compiles the part, checks its object and stores the verdict in the
//! cache. A part that does not compile is not stored and comes back
//! missing, `why` saying so (the program's own compile tells the user
//! what is wrong).
declarations_part build_declarations(const declarations_request& request);

//! Stores, for this key, that the part could not serve its program (it did
//! not compile or link, where the program compiled whole): later builds
//! compile the program whole at once.
void record_unusable(const std::string& cache_dir, const std::string& key, const std::string& why);

}  // namespace vvi
