// Quick builds, for the first seconds after an edit: the program compiled
// unoptimised by clang (about half a second where g++ at -O1 takes two),
// linked with the optimised declarations' part the last build left in the
// cache (declarations_part.hpp). The viewer runs it at once and swaps in
// the optimised build when that is ready (control/model_loads.cpp);
// batch runs with --expect-edits run it as it is.
//
// Both builds compute the same numbers: x86-64 has no fused multiply-add
// without -march, both use the same libm, and the part's code is the
// optimised build's own. clang's OpenMP runtime (libomp) also serves the
// part's g++ loops, through its GNU entry points.
#pragma once

#include <string>
#include <vector>

#include "compile/declarations_header.hpp"
#include "compile/precompiled_header.hpp"

namespace vvi {

//! Whether this interpreter was built with a clang that has OpenMP.
bool quick_builds_available();

//! The flags of a quick build and of its precompiled header.
std::vector<std::string> quick_flags(const std::string& include);

//! The precompiled header of quick builds, in the cache's pch/ folder.
header_request quick_header(const std::string& cache_dir, const std::string& include, const std::string& stamp);

//! What the program is compiled with besides quick_flags(), and so the
//! header of its declarations too (they must match).
std::vector<std::string> quick_program_flags(const std::string& model_dir);

//! The header of a model's declarations (declarations_header.hpp) for
//! quick builds on the vvlib header `vvlib_pch`: `text` is vvc's
//! (translation::header).
declarations_header_request quick_declarations_header(const std::string& cache_dir, const std::string& include,
                                                      const std::string& model_dir, const std::string& vvlib_pch,
                                                      const std::string& text);

struct quick_job {
  std::string header_file;             // model.hpp.pch, or the declarations' header.hpp.pch
  std::string include;                 // vvlib's headers
  std::string model_dir;               // the model's own headers
  std::string work;                    // holds the source; model.so and model.d are made there
  std::string part;                    // the declarations' part's object
  std::vector<std::string> libraries;  // the headers' code, -L, -l... for the link
  std::string source = "model.cpp";    // in work: the whole text, or the program apart from its header
};

//! The one command that compiles the program and links it with the part.
std::vector<std::string> quick_command(const quick_job& job);

}  // namespace vvi
