// The precompiled model/model.hpp every model includes first: built
// once per cache, compiler and set of flags (a few seconds), in the cache's
// pch/ folder (model_cache.hpp), and checked before each use. g++ finds
// model/model.hpp.gch on the include path; clang (quick builds,
// quick_build.hpp) is given model/model.hpp.pch with -include-pch.
//
// clang at -O0 (quick builds, the sanitizer build's models) also compiles
// the header's inline functions and templates once, into model.hpp.o
// (-fpch-codegen): a model then compiles only its own code, a third less,
// and links the object with --gc-sections, which keeps what it uses.
// Optimised builds compile them in each model, where they can be inlined.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct header_request {
  std::string cache_dir;           // holds pch/
  std::string include;             // vvlib's headers
  std::vector<std::string> flags;  // the flags models are compiled with (they must match)
  std::string key;                 // a hash of the compiler, the flags and the headers
  std::string compiler;            // g++ (config::cxx_compiler), or clang for quick builds
  bool clang = false;              // model.hpp.pch, its templates instantiated once in it
  bool codegen = false;            // clang at -O0: and their code in model.hpp.o
};

//! The request for the header models compiled by `compiler` with `flags`
//! share (`stamp`: of vvlib's headers).
header_request make_header_request(const std::string& cache_dir, const std::string& include,
                                   const std::vector<std::string>& flags, const std::string& compiler, bool clang,
                                   const std::string& stamp);

//! The header's file in a folder precompiled_header_dir returned.
std::string precompiled_header_file(const std::string& dir, bool clang);

//! What a model compiled with the header in `dir` links besides: its
//! code's object (codegen), or nothing.
std::vector<std::string> precompiled_header_link(const std::string& dir, const header_request& request);

//! The folder of the header (g++: to put first on the include path, as it
//! holds model/model.hpp.gch), built when the cache has no sound one. ""
//! when it cannot be built (`error` says why; models then compile without
//! it). `damage` says why a cached one was found broken and rebuilt, or "".
std::string precompiled_header_dir(const header_request& request, std::string& damage, std::string& error);

//! Removes a build of the header the compiler could not read, so that the
//! next precompiled_header_dir builds it afresh.
void discard_precompiled_header(const std::string& dir);

//! Whether the compiler's output says it could not read a precompiled
//! header (g++'s words, or clang's for a damaged or outdated one).
bool unreadable_precompiled_header(const std::string& compiler_output);

}  // namespace vvi
